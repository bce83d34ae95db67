package gfx.tick1.command.shared.diagnosis;

import static gfx.tick1.command.shared.behaviour.Variant.BACKGROUND_ONLY;
import static gfx.tick1.command.shared.behaviour.Variant.RED_BLUE_SWAPPED;
import static gfx.tick1.command.shared.behaviour.Variant.ROUNDED_BYTES;
import static gfx.tick1.command.shared.behaviour.Variant.UPSIDE_DOWN;

import gfx.tick1.command.shared.behaviour.Models;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.Camera;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.render.Renderer;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.awt.image.BufferedImage;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.Map;
import java.util.Set;
import java.util.stream.IntStream;

/**
 * The reference renderer with one thing done the way a student might do it: each {@link Variant}
 * changes exactly the line where that slip happens, and everything else is written in the same
 * order as {@link Renderer}, so that {@link Variant#CORRECT} gives the reference image pixel for
 * pixel (a test holds the two together) and every mistake gives the image a student's code with
 * that mistake would make.
 */
public final class VariantRenderer {

    private final int width, height;

    public VariantRenderer(int width, int height) {
        this.width = width;
        this.height = height;
    }

    /** The image of {@code scene} as {@code variant} renders it. */
    public BufferedImage render(Scene scene, Variant variant) {
        return render(scene, EnumSet.of(variant)).get(variant);
    }

    /**
     * The images of {@code scene} as each of {@code variants} renders it, rows shared among the
     * cores. Each ray is intersected once for all of them (the costly part on scenes of many
     * spheres); only the shading and the writing of the pixel differ.
     */
    public Map<Variant, BufferedImage> render(Scene scene, Set<Variant> variants) {
        return renders(scene, variants).images();
    }

    /**
     * The images of a scene as several entries render it, and the pixels where at least one of
     * them draws a sphere (where its ray hits one, in the row it writes the pixel to).
     *
     * @param spheres one flag a pixel, row by row from the top
     */
    public record Renders(Map<Variant, BufferedImage> images, boolean[] spheres) {
    }

    /** As {@link #render(Scene, Set)}, with the pixels where some entry draws a sphere. */
    public Renders renders(Scene scene, Set<Variant> variants) {
        Camera camera = new Camera(width, height);
        Map<Variant, int[]> pixels = new EnumMap<>(Variant.class);
        Map<Variant, Set<Variant>> alone = new EnumMap<>(Variant.class);
        variants.forEach(variant -> {
            pixels.put(variant, new int[width * height]);
            alone.put(variant, EnumSet.of(variant));
        });
        // Rows are written by one thread each, but an upside-down row lands in another's: every
        // write sets a flag to true, which no other write undoes (JLS 17.6: no word tearing).
        boolean[] spheres = new boolean[width * height];
        IntStream.range(0, height).parallel().forEach(y -> {
            for (int x = 0; x < width; x++) {
                Ray ray = camera.castRay(x, y);
                RaycastHit nearHit = scene.findClosestIntersection(ray);
                for (Variant variant : variants) {
                    // The reference's own hit for every entry that keeps intersectionWith as it is.
                    RaycastHit hit = variant.method() == Variant.Method.INTERSECTION_WITH
                            ? closestHit(scene, ray, alone.get(variant)) : nearHit;
                    Vector3 colour = shade(scene, hit, variant, alone.get(variant));
                    // Pixel row 0 is the top of the image; writing rows bottom-up turns the picture over.
                    int row = variant == UPSIDE_DOWN ? height - 1 - y : y;
                    pixels.get(variant)[row * width + x] = toRGB(colour, variant);
                    if (variant != BACKGROUND_ONLY && hit.getObjectHit() != null) {
                        spheres[row * width + x] = true;
                    }
                }
            }
        });
        Map<Variant, BufferedImage> images = new EnumMap<>(Variant.class);
        pixels.forEach((variant, rgb) -> {
            BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
            image.setRGB(0, 0, width, height, rgb, 0, width);
            images.put(variant, image);
        });
        return new Renders(images, spheres);
    }

    /** Renderer.trace after the intersection: the background, or the shade of the hit. */
    static Vector3 shade(Scene scene, RaycastHit hit, Variant variant, Set<Variant> model) {
        if (variant == BACKGROUND_ONLY || hit.getObjectHit() == null) {
            return ReferenceRenderer.BACKGROUND_COLOUR;
        }
        Sphere object = hit.getObjectHit();
        return Models.illuminate(new Models.Shading(scene.getAmbientLighting(), scene.getPointLight(),
                new Models.Surface(object.getColour(), object.getPhong_kD(), object.getPhong_kS(), object.getPhong_n()),
                hit.getLocation(), hit.getNormal()), model);
    }

    /**
     * Scene.findClosestIntersection over the model of intersectionWith: a later sphere replaces
     * the hit only when its distance is smaller (a NaN distance never is), as the starter's Scene does.
     */
    static RaycastHit closestHit(Scene scene, Ray ray, Set<Variant> model) {
        RaycastHit closest = new RaycastHit();
        for (Sphere sphere : scene.getObjects()) {
            Models.Hit hit = Models.intersect(ray.getOrigin(), ray.getDirection(),
                    SphereGeometry.centre(sphere), SphereGeometry.radius(sphere), model);
            if (hit != null && hit.distance() < closest.getDistance()) {
                closest = new RaycastHit(sphere, hit.distance(), hit.point(), hit.normal());
            }
        }
        return closest;
    }

    /** Colour to 0xRRGGBB: Vector3.toRGB, or rounded, or with red and blue exchanged. */
    private static int toRGB(Vector3 colour, Variant variant) {
        return switch (variant) {
            case ROUNDED_BYTES -> rounded(colour.x) << 16 | rounded(colour.y) << 8 | rounded(colour.z);
            case RED_BLUE_SWAPPED -> Vector3.toByte(colour.z) << 16 | Vector3.toByte(colour.y) << 8
                    | Vector3.toByte(colour.x);
            default -> colour.toRGB();
        };
    }

    private static int rounded(double channel) {
        return (int) Math.round(255 * Math.max(0, Math.min(1, channel)));
    }
}
