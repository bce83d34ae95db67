package gfx.tick1.engine.render;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.fast.FastRenderer;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.awt.image.BufferedImage;
import java.util.Random;
import java.util.stream.LongStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The renderer against a straight transcription of the spec in bare doubles, on generated
 * scenes of the ordinary kind: the two must agree on every pixel. The transcription is written
 * independently of Vector3 (it only shares the order of operations, which the handout's figures
 * pin down), so a refactoring or a fast path that changes a single rounding shows up here.
 */
class PlainSpecOracleTest {

    private static final int W = 160, H = 120;

    static LongStream seeds() {
        return LongStream.rangeClosed(1, 64);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rendererMatchesThePlainSpecOnEveryPixel(long seed) {
        Random random = new Random(seed);
        Scene scene = new Scene();
        if (random.nextInt(4) > 0) {
            scene.setAmbientLight(new Vector3(random.nextDouble(), random.nextDouble(), random.nextDouble()));
        }
        scene.setPointLight(new PointLight(new Vector3(gauss(random, 3), gauss(random, 3), random.nextDouble() * 8),
                colour(random), 20 + random.nextDouble() * 400));
        int spheres = 1 + random.nextInt(12);
        for (int i = 0; i < spheres; i++) {
            scene.addObject(new Sphere(new Vector3(gauss(random, 2), gauss(random, 1.5), 3 + random.nextDouble() * 8),
                    0.2 + random.nextDouble() * 1.5, colour(random)));
        }

        assertMatchesThePlainSpec(scene, new ReferenceRenderer(W, H).render(scene), "readable Renderer");
        // The command line's renderer, as an outside check that renders unseen scenes sees it.
        assertMatchesThePlainSpec(scene, new FastRenderer(W, H, new SamplePattern(1)).render(scene), "fast renderer");
    }

    private static void assertMatchesThePlainSpec(Scene scene, BufferedImage image, String renderer) {
        int differing = 0;
        String first = null;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int expected = plainSpecPixel(scene, x, y), actual = image.getRGB(x, y) & 0xFFFFFF;
                if (expected != actual) {
                    differing++;
                    first = first != null ? first
                            : String.format("(%d, %d): %06X, spec says %06X", x, y, actual, expected);
                }
            }
        }
        assertThat(differing).as("%s: pixels differing from the plain spec, first at %s", renderer, first).isZero();
    }

    private static double gauss(Random random, double sigma) {
        return random.nextGaussian() * sigma;
    }

    private static Vector3 colour(Random random) {
        return new Vector3(random.nextInt(256) / 255.0, random.nextInt(256) / 255.0, random.nextInt(256) / 255.0);
    }

    /** The spec, section by section, in bare doubles. */
    private static int plainSpecPixel(Scene scene, int px, int py) {
        // Camera and image.
        double widthM = 2 * Math.tan(Math.toRadians(45) / 2);
        double heightM = widthM / ((double) W / (double) H);
        double xStep = widthM / W, yStep = heightM / H;
        double dx = (xStep - widthM) / 2 + px * xStep, dy = (yStep + heightM) / 2 - py * yStep, dz = 1;
        double dLength = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= dLength;
        dy /= dLength;
        dz /= dLength;

        // Intersection: nearest root with s > 0; earlier sphere wins ties.
        double nearest = Double.POSITIVE_INFINITY;
        Sphere hit = null;
        for (Sphere sphere : scene.getObjects()) {
            Vector3 c = SphereGeometry.centre(sphere);
            double fx = 0 - c.x, fy = 0 - c.y, fz = 0 - c.z;
            double a = dx * dx + dy * dy + dz * dz;
            double b = 2 * (dx * fx + dy * fy + dz * fz);
            double cc = (fx * fx + fy * fy + fz * fz) - Math.pow(SphereGeometry.radius(sphere), 2);
            double disc = b * b - 4 * a * cc;
            if (disc < 0) {
                continue;
            }
            double s1 = (-b - Math.sqrt(disc)) / (2 * a), s2 = (-b + Math.sqrt(disc)) / (2 * a);
            double s = s1 > 0 ? s1 : s2;
            if (s > 0 && s < nearest) {
                nearest = s;
                hit = sphere;
            }
        }
        if (hit == null) {
            return 0x191919;
        }

        // Shading at P with normal N.
        double x = 0 + nearest * dx, y = 0 + nearest * dy, z = 0 + nearest * dz;
        Vector3 c = SphereGeometry.centre(hit);
        double nx = x - c.x, ny = y - c.y, nz = z - c.z;
        double nLength = Math.sqrt(nx * nx + ny * ny + nz * nz);
        nx /= nLength;
        ny /= nLength;
        nz /= nLength;

        Vector3 ambient = scene.getAmbientLighting(), diffuseColour = hit.getColour();
        PointLight light = scene.getPointLight();
        Vector3 lp = light.getPosition();
        double lx = lp.x - x, ly = lp.y - y, lz = lp.z - z;
        double distance = Math.sqrt(lx * lx + ly * ly + lz * lz);
        double falloff = light.getIntensity() / (Math.PI * 4 * Math.pow(distance, 2));
        double ir = falloff * light.getColour().x;
        double ig = falloff * light.getColour().y;
        double ib = falloff * light.getColour().z;
        lx /= distance;
        ly /= distance;
        lz /= distance;
        double vLength = Math.sqrt(x * x + y * y + z * z);
        double vx = -x / vLength, vy = -y / vLength, vz = -z / vLength;
        double nDotL = nx * lx + ny * ly + nz * lz;
        double twice = 2 * nDotL;
        double rx = twice * nx - lx, ry = twice * ny - ly, rz = twice * nz - lz;
        double rDotV = rx * vx + ry * vy + rz * vz;
        double kd = 0.8 * Math.max(0, nDotL), ks = 0.8 * Math.pow(Math.max(0, rDotV), 10);

        double r = diffuseColour.x * ambient.x + kd * (diffuseColour.x * ir) + ks * (1 * ir);
        double g = diffuseColour.y * ambient.y + kd * (diffuseColour.y * ig) + ks * (1 * ig);
        double b = diffuseColour.z * ambient.z + kd * (diffuseColour.z * ib) + ks * (1 * ib);
        return toByte(r) << 16 | toByte(g) << 8 | toByte(b);
    }

    private static int toByte(double channel) {
        return (int) (255 * Math.max(0, Math.min(1, channel)));
    }
}
