package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.behaviour.BehaviourJudge.RayCase;
import gfx.tick1.command.shared.behaviour.BehaviourJudge.ShadeCase;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs.Chosen;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs.IlluminationCall;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs.IntersectionCall;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.engine.io.Counted;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.Camera;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;

/**
 * The input where a student's methods differ from ours, found on the image itself: when their
 * image differs from ours but every fixed and random input gave our answer, their
 * {@code intersectionWith} is called on the camera rays of the differing pixels, with every sphere
 * of the scene, and their {@code illuminate} on what our hit there is; the first answer that is not
 * ours is the counterexample, with the pixel it came from. The pixels are taken in the image's
 * order, row by row, at most {@link #MOST_PIXELS}.
 */
public final class PixelCounterexample {

    /** The student's two files, and the sandbox their methods run in. */
    public record Code(String sphere, String renderer, Sandbox sandbox) {
    }

    /** What the calls found, in words: where an answer differs from ours, or that none does. */
    public record Found(boolean differs, String words) {
    }

    /** The most differing pixels whose rays are asked about: enough for a mistake at the outlines. */
    static final int MOST_PIXELS = 200;

    private PixelCounterexample() {
    }

    /** A pixel and the inputs of its ray: one intersection a sphere, and the shading at our hit (or none). */
    private record PixelInputs(int x, int y, List<IntersectionCall> rays, IlluminationCall shading) {
    }

    /**
     * What the calls on the differing pixels of {@code image} (ours: {@code reference}) of
     * {@code scene}, named {@code name}, found; null when the methods could not be run.
     */
    public static Found find(Code code, Scene scene, String name, BufferedImage reference, BufferedImage image)
            throws InterruptedException {
        List<PixelInputs> pixels = pixels(scene, reference, image);
        List<IntersectionCall> rays = new ArrayList<>();
        List<IlluminationCall> shadings = new ArrayList<>();
        for (PixelInputs pixel : pixels) {
            rays.addAll(pixel.rays());
            if (pixel.shading() != null) {
                shadings.add(pixel.shading());
            }
        }
        Chosen chosen = new Chosen(rays, shadings);
        BehaviourCheck.Called called = BehaviourCheck.call(code.sandbox(), code.sphere(), code.renderer(), chosen);
        if (called.log() == null) {
            return null;
        }
        Answers answers = Answers.parse(called.log(), chosen);
        if (!answers.any()) {
            return null;
        }
        for (PixelInputs pixel : pixels) {
            String at = "at pixel (" + pixel.x() + ", " + pixel.y() + ") of " + name + ", ";
            for (IntersectionCall ray : pixel.rays()) {
                RayCase asked = new RayCase(ray, answers.get(ray.name()));
                if (!asked.isOurs()) {
                    return new Found(true, "your intersectionWith differs from ours " + at + asked.counterexample());
                }
            }
            if (pixel.shading() != null) {
                ShadeCase asked = new ShadeCase(pixel.shading(), answers.get(pixel.shading().name()),
                        BehaviourInputs.Phong.FIXED);
                if (!asked.isOurs()) {
                    return new Found(true, "your illuminate differs from ours " + at + asked.counterexample());
                }
            }
        }
        return new Found(false, "and on the rays of the first " + Counted.of(pixels.size(), "differing pixel")
                + " of " + name + " too: your intersectionWith gives our answer there for every sphere, and your "
                + "illuminate ours at our hit, within " + Words.number(BehaviourJudge.TOLERANCE)
                + " of each number's size");
    }

    /** The differing pixels' inputs, row by row, at most {@link #MOST_PIXELS}. */
    private static List<PixelInputs> pixels(Scene scene, BufferedImage reference, BufferedImage image) {
        Camera camera = new Camera(image.getWidth(), image.getHeight());
        List<Sphere> spheres = scene.getObjects();
        List<PixelInputs> pixels = new ArrayList<>();
        for (int y = 0; y < image.getHeight() && pixels.size() < MOST_PIXELS; y++) {
            for (int x = 0; x < image.getWidth() && pixels.size() < MOST_PIXELS; x++) {
                if ((reference.getRGB(x, y) & 0xFFFFFF) == (image.getRGB(x, y) & 0xFFFFFF)) {
                    continue;
                }
                Ray ray = camera.castRay(x, y);
                List<IntersectionCall> rays = new ArrayList<>();
                for (int s = 0; s < spheres.size(); s++) {
                    Sphere sphere = spheres.get(s);
                    rays.add(new IntersectionCall("pixel" + pixels.size() + "-sphere" + s, xyz(ray.getOrigin()),
                            xyz(ray.getDirection()), xyz(SphereGeometry.centre(sphere)),
                            SphereGeometry.radius(sphere)));
                }
                // Our hit there, as the reference renders it.
                RaycastHit ours = scene.findClosestIntersection(ray);
                pixels.add(new PixelInputs(x, y, rays, !ours.isHit() || scene.getPointLight() == null ? null
                        : shading("pixel" + pixels.size(), scene, ours)));
            }
        }
        return pixels;
    }

    private static IlluminationCall shading(String name, Scene scene, RaycastHit hit) {
        PointLight light = scene.getPointLight();
        Sphere sphere = hit.getObjectHit();
        return new IlluminationCall(name, xyz(scene.getAmbientLighting()),
                new BehaviourInputs.LightInput(xyz(light.getPosition()), xyz(light.getColour()), light.getIntensity()),
                new BehaviourInputs.SphereInput(xyz(SphereGeometry.centre(sphere)), SphereGeometry.radius(sphere),
                        new BehaviourInputs.Material(xyz(sphere.getColour()), sphere.getPhong_kD(),
                                sphere.getPhong_kS(), sphere.getPhong_n())),
                xyz(hit.getLocation()), xyz(hit.getNormal()));
    }

    private static double[] xyz(Vector3 v) {
        return new double[] {v.x, v.y, v.z};
    }
}
