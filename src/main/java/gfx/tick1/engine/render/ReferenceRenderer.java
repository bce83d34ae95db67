package gfx.tick1.engine.render;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import java.awt.image.BufferedImage;
import java.util.stream.IntStream;

/**
 * The readable reference render that the rest of the program and the tests use: {@link Renderer}'s
 * own {@code trace} (and so its {@code illuminate}) on every pixel, with what the tick does not ask
 * for kept here, so that Renderer.java stays what a student writes: rows shared among the cores,
 * anti-aliasing ({@link SamplePattern}), the intersection method, no line printed per row, and
 * scenes without a point light. Each pixel is computed alone, so the image is the same as
 * {@code Renderer.render}'s.
 */
public class ReferenceRenderer extends Renderer {

    /** Renderer's background colour, 0.1 grey, for the code that traces without it. */
    public static final Vector3 BACKGROUND_COLOUR = new Vector3(0.1);

    private final int width, height;
    private final Intersection intersection;

    public ReferenceRenderer(int width, int height) {
        this(width, height, Intersection.DEFAULT);
    }

    /** A renderer that intersects rays with spheres by the given method. */
    public ReferenceRenderer(int width, int height, Intersection intersection) {
        super(width, height);
        this.width = width;
        this.height = height;
        this.intersection = intersection;
    }

    /**
     * Renderer.trace, except for a scene without a point light, which the loader allows (with a
     * warning) but Renderer.illuminate cannot shade, as it asks the light for its position first:
     * there only the ambient term C_diff I_a is seen.
     */
    @Override
    protected Vector3 trace(Scene scene, Ray ray) {
        if (scene.getPointLight() != null) {
            return super.trace(scene, ray);
        }
        RaycastHit closestHit = scene.findClosestIntersection(ray);
        Sphere object = closestHit.getObjectHit();
        return object == null ? BACKGROUND_COLOUR : object.getColour().scale(scene.getAmbientLighting());
    }

    /** The image through pixel centres, rows shared among the cores. */
    @Override
    public BufferedImage render(Scene scene) {
        return render(scene, new SamplePattern(1));
    }

    /**
     * Renders the scene, rows shared among the cores. With one sample, one {@code castRay} per
     * pixel through its centre; with more, the average of the samples' colours, taken before
     * the conversion to bytes.
     */
    public BufferedImage render(Scene scene, SamplePattern samples) {
        Scene traced = scene.using(intersection);
        Camera camera = new Camera(width, height);
        int[] pixels = new int[width * height];
        IntStream.range(0, height).parallel().forEach(y -> {
            for (int x = 0; x < width; x++) {
                pixels[y * width + x] = pixel(traced, camera, samples, x, y).toRGB();
            }
        });
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, pixels, 0, width);
        return image;
    }

    /** The mean colour of the pixel's samples; one sample is exactly the ray through its centre. */
    private Vector3 pixel(Scene scene, Camera camera, SamplePattern samples, int x, int y) {
        Vector3 sum = trace(scene, camera.castRay(x + samples.dx(0), y + samples.dy(0)));
        for (int i = 1; i < samples.size(); i++) {
            sum = sum.add(trace(scene, camera.castRay(x + samples.dx(i), y + samples.dy(i))));
        }
        return sum.scale(1.0 / samples.size());
    }
}
