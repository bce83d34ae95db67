package gfx.tick1.diagnose;

import static gfx.tick1.diagnose.Variant.AMBIENT_DIFFUSE;
import static gfx.tick1.diagnose.Variant.AMBIENT_ONLY;
import static gfx.tick1.diagnose.Variant.AMBIENT_WITHOUT_C_DIFF;
import static gfx.tick1.diagnose.Variant.BACKGROUND_ONLY;
import static gfx.tick1.diagnose.Variant.COLOUR_OVER_255;
import static gfx.tick1.diagnose.Variant.COLOUR_TIMES_255;
import static gfx.tick1.diagnose.Variant.FALL_OFF_WITHOUT_4PI;
import static gfx.tick1.diagnose.Variant.FAR_ROOT;
import static gfx.tick1.diagnose.Variant.FLAT_COLOUR;
import static gfx.tick1.diagnose.Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT;
import static gfx.tick1.diagnose.Variant.NO_AMBIENT;
import static gfx.tick1.diagnose.Variant.NO_FALL_OFF;
import static gfx.tick1.diagnose.Variant.RED_BLUE_SWAPPED;
import static gfx.tick1.diagnose.Variant.ROUNDED_BYTES;
import static gfx.tick1.diagnose.Variant.ROOTS_ACCEPTED_AT_ZERO;
import static gfx.tick1.diagnose.Variant.R_WRONG_WAY;
import static gfx.tick1.diagnose.Variant.SPECULAR_WITHOUT_I;
import static gfx.tick1.diagnose.Variant.UNCLAMPED_N_DOT_L;
import static gfx.tick1.diagnose.Variant.UNCLAMPED_R_DOT_V;
import static gfx.tick1.diagnose.Variant.UNNORMALISED_L_V;
import static gfx.tick1.diagnose.Variant.UPSIDE_DOWN;
import static gfx.tick1.diagnose.Variant.V_AWAY_FROM_CAMERA;

import gfx.tick1.math.Ray;
import gfx.tick1.math.Vector3;
import gfx.tick1.render.Camera;
import gfx.tick1.render.ReferenceRenderer;
import gfx.tick1.render.Renderer;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.PointLight;
import gfx.tick1.scene.RaycastHit;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.Sphere;
import gfx.tick1.scene.SphereGeometry;
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
        variants.forEach(variant -> pixels.put(variant, new int[width * height]));
        // Rows are written by one thread each, but an upside-down row lands in another's: every
        // write sets a flag to true, which no other write undoes (JLS 17.6: no word tearing).
        boolean[] spheres = new boolean[width * height];
        boolean needsFarRoot = variants.contains(FAR_ROOT);
        boolean needsBothRootsPositive = variants.contains(HIT_REJECTED_ON_A_NEGATIVE_ROOT);
        boolean needsZeroRoots = variants.contains(ROOTS_ACCEPTED_AT_ZERO);
        IntStream.range(0, height).parallel().forEach(y -> {
            for (int x = 0; x < width; x++) {
                Ray ray = camera.castRay(x, y);
                RaycastHit nearHit = scene.findClosestIntersection(ray);
                RaycastHit farHit = needsFarRoot ? farthestRootHit(scene, ray) : null;
                RaycastHit bothRootsHit = needsBothRootsPositive ? bothRootsPositiveHit(scene, ray) : null;
                RaycastHit zeroRootHit = needsZeroRoots ? zeroRootHit(scene, ray, nearHit) : null;
                for (Variant variant : variants) {
                    RaycastHit hit = switch (variant) {
                        case FAR_ROOT -> farHit;
                        case HIT_REJECTED_ON_A_NEGATIVE_ROOT -> bothRootsHit;
                        case ROOTS_ACCEPTED_AT_ZERO -> zeroRootHit;
                        default -> nearHit;
                    };
                    Vector3 colour = shade(scene, hit, variant);
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
    private static Vector3 shade(Scene scene, RaycastHit hit, Variant variant) {
        if (variant == BACKGROUND_ONLY || hit.getObjectHit() == null) {
            return ReferenceRenderer.BACKGROUND_COLOUR;
        }
        return illuminate(scene, hit.getObjectHit(), hit.getLocation(), hit.getNormal(), variant);
    }

    /** Renderer.illuminate, with each variant's change at the line where it happens. */
    private static Vector3 illuminate(Scene scene, Sphere object, Vector3 P, Vector3 N, Variant variant) {
        Vector3 I_a = scene.getAmbientLighting();
        Vector3 C_diff = object.getColour();
        if (variant == FLAT_COLOUR) {
            return C_diff;
        }
        Vector3 ambient = variant == AMBIENT_WITHOUT_C_DIFF ? I_a : C_diff.scale(I_a);

        PointLight light = scene.getPointLight();
        if (light == null || variant == AMBIENT_ONLY) {
            return variant == NO_AMBIENT ? new Vector3(0) : ambient;
        }
        double distanceToLight = light.getPosition().subtract(P).magnitude();
        Vector3 I = illumination(light, distanceToLight, variant);
        Vector3 C_spec = new Vector3(1);

        double k_d = object.getPhong_kD();
        double k_s = object.getPhong_kS();
        double n = object.getPhong_n();

        Vector3 toLight = light.getPosition().subtract(P);
        Vector3 L = variant == UNNORMALISED_L_V ? toLight : toLight.normalised();
        Vector3 V = switch (variant) {
            case UNNORMALISED_L_V -> P.scale(-1);
            case V_AWAY_FROM_CAMERA -> P.normalised(); // from the camera at the origin towards P
            default -> P.scale(-1).normalised();
        };
        Vector3 R = variant == R_WRONG_WAY ? N.reflectIn(L) : L.reflectIn(N);

        double NdotL = N.dot(L);
        double RdotV = R.dot(V);
        double diffuseFactor = variant == UNCLAMPED_N_DOT_L ? NdotL : Math.max(0, NdotL);
        double specularBase = variant == UNCLAMPED_R_DOT_V ? RdotV : Math.max(0, RdotV);

        Vector3 diffuse = C_diff.scale(I).scale(k_d * diffuseFactor);
        if (variant == AMBIENT_DIFFUSE) {
            return ambient.add(diffuse);
        }
        Vector3 specular = variant == SPECULAR_WITHOUT_I ? C_spec.scale(k_s * Math.pow(specularBase, n))
                : C_spec.scale(I).scale(k_s * Math.pow(specularBase, n));
        return switch (variant) {
            case NO_AMBIENT -> diffuse.add(specular);
            case COLOUR_TIMES_255 -> ambient.add(diffuse).add(specular).scale(255);
            case COLOUR_OVER_255 -> ambient.add(diffuse).add(specular).scale(1.0 / 255);
            default -> ambient.add(diffuse).add(specular);
        };
    }

    /** I = light colour * intensity / (4 pi d^2), or one of the two ways of getting it wrong. */
    private static Vector3 illumination(PointLight light, double distance, Variant variant) {
        return switch (variant) {
            case NO_FALL_OFF -> light.getColour().scale(light.getIntensity() / (Math.PI * 4));
            case FALL_OFF_WITHOUT_4PI -> light.getColour().scale(light.getIntensity() / Math.pow(distance, 2));
            default -> light.getIlluminationAt(distance);
        };
    }

    /**
     * The nearest sphere as seen through the far root s2 = (-b + sqrt(b^2 - 4ac)) / 2a of each
     * sphere's quadratic, computed as Sphere.intersectionWith computes it.
     */
    private static RaycastHit farthestRootHit(Scene scene, Ray ray) {
        RaycastHit closest = new RaycastHit();
        for (Sphere sphere : scene.getObjects()) {
            double s2 = root(sphere, ray, true);
            if (s2 > 0 && s2 < closest.getDistance()) { // false for NaN: the ray misses
                Vector3 point = ray.evaluateAt(s2);
                closest = new RaycastHit(sphere, s2, point, sphere.getNormalAt(point));
            }
        }
        return closest;
    }

    /**
     * The nearest hit when a sphere counts only if both roots of its quadratic are positive: a
     * sphere with the ray's origin inside it (roots of opposite signs, c &lt; 0) is never hit.
     * Every other sphere is hit where the reference hits it.
     */
    private static RaycastHit bothRootsPositiveHit(Scene scene, Ray ray) {
        RaycastHit closest = new RaycastHit();
        for (Sphere sphere : scene.getObjects()) {
            RaycastHit hit = Intersection.DEFAULT.find(sphere, ray);
            if (hit.getDistance() < closest.getDistance() && !(root(sphere, ray, false) < 0)) {
                closest = hit;
            }
        }
        return closest;
    }

    /**
     * The hit when a root s = 0 counts (s = s1 &gt;= 0 ? s1 : s2, a hit if s &gt;= 0): where a
     * sphere's surface passes exactly through the ray's origin, that sphere at distance 0, the
     * nearest any hit can be (the first such sphere on a tie, as Scene keeps the first of equal
     * hits); elsewhere the reference's hit, as no root is 0 there.
     */
    private static RaycastHit zeroRootHit(Scene scene, Ray ray, RaycastHit nearHit) {
        for (Sphere sphere : scene.getObjects()) {
            double s1 = root(sphere, ray, false);
            double s = s1 >= 0 ? s1 : root(sphere, ray, true);
            if (s == 0) {
                Vector3 point = ray.evaluateAt(s);
                return new RaycastHit(sphere, s, point, sphere.getNormalAt(point));
            }
        }
        return nearHit;
    }

    /**
     * s1 = (-b - sqrt(b^2 - 4ac)) / 2a or, if {@code far}, s2 = (-b + sqrt(b^2 - 4ac)) / 2a, as
     * Sphere.intersectionWith computes them; NaN when the discriminant is negative.
     */
    private static double root(Sphere sphere, Ray ray, boolean far) {
        Vector3 O = ray.getOrigin();
        Vector3 D = ray.getDirection();
        Vector3 C = SphereGeometry.centre(sphere);
        double a = D.dot(D);
        double b = 2 * D.dot(O.subtract(C));
        double c = O.subtract(C).dot(O.subtract(C)) - Math.pow(SphereGeometry.radius(sphere), 2);
        double discriminant = b * b - 4 * a * c;
        return far ? (-b + Math.sqrt(discriminant)) / (2 * a) : (-b - Math.sqrt(discriminant)) / (2 * a);
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
