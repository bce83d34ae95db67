package gfx.tick1.command.shared.grader.harness;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The fixed inputs on which the harness calls a student's {@code Sphere.intersectionWith} and
 * {@code Renderer.illuminate}. Each call has a name; the harness reports what it returned by that
 * name, and the grader, which holds the same inputs, decides what the answers mean. The inputs are
 * chosen so that the answers are round numbers: the rays of the intersections have unit
 * directions, the lights of the illuminations are at distance 1 or 2 with intensity 4 pi (so that
 * I = 1 or 1/4), and the camera is at distance 1 or 2 from the point shaded. After them come
 * {@link #RANDOM_COUNT} seeded random inputs for each method, in round numbers, made the same way
 * in the harness and in the grader: what the course's scenes never vary (directions that are not
 * unit vectors, origins away from zero, radii other than 1, coloured spheres and lights, k_d other
 * than k_s, n other than 10, any P and N) varies there.
 */
public final class BehaviourInputs {

    private BehaviourInputs() {
    }

    /** A ray (origin O, direction D) and a sphere (centre C, radius r) for intersectionWith. */
    public record IntersectionCall(String name, double[] origin, double[] direction, double[] centre, double radius) {
    }

    /**
     * A scene (ambient light, one point light), a sphere, and the point P and unit normal N to shade
     * on it, for illuminate.
     */
    public record IlluminationCall(String name, double[] ambient, LightInput light, SphereInput sphere, double[] point,
            double[] normal) {
    }

    /** A point light: where it is, its colour, and its intensity. */
    public record LightInput(double[] position, double[] colour, double intensity) {
    }

    /** A sphere: its centre, its radius and its material. */
    public record SphereInput(double[] centre, double radius, Material material) {
    }

    /**
     * Whether the student's spheres take the Phong coefficients k_d, k_s and n they are given (the Sphere has
     * setPhong) or keep the course's; the word names it in the answer log.
     */
    public enum Phong {
        SET, FIXED;

        public String word() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /** A sphere's material: its colour C_diff and its Phong coefficients k_d, k_s and n. */
    public record Material(double[] colour, double kD, double kS, double n) {

        /** Of {@code colour}, with the course's coefficients k_d = k_s = 0.8 and n = 10. */
        static Material course(double[] colour) {
            return new Material(colour, COURSE_KD, COURSE_KS, COURSE_N);
        }
    }

    /** The Phong coefficients of every sphere of the course: a Sphere's constructor sets them. */
    public static final double COURSE_KD = 0.8, COURSE_KS = 0.8, COURSE_N = 10;

    private static final double FOUR_PI = 4 * Math.PI;
    private static final double[] ORIGIN = {0, 0, 0}, ALONG_Z = {0, 0, 1}, WHITE = {1, 1, 1}, BLACK = {0, 0, 0};
    /** An origin off the axes and a unit direction, so that code that assumes O = 0 shows it. */
    private static final double[] OFF_ORIGIN = {1, -1, 0.5}, SLANT = {0.6, 0, 0.8};
    /** On the sphere of centre (0, 0, 2) and radius 1, the point nearest the camera, facing it. */
    private static final double[] NEAR_POINT = {0, 0, 1}, TOWARDS_CAMERA = {0, 0, -1}, NEAR_CENTRE = {0, 0, 2};
    /** A colour with no green: green is then the specular term alone, red minus green the diffuse. */
    private static final double[] NO_GREEN = {0.5, 0, 0.25};
    /** A light of intensity 0: the ambient term alone. */
    private static final LightInput DARK = new LightInput(new double[] {0, 0, 5}, WHITE, 0);

    /** Rays and spheres: a hit, a miss, a graze, a ray pointing away, a sphere behind, inside, on the surface. */
    public static final List<IntersectionCall> INTERSECTIONS = List.of(
            // C = O + 5 D: roots s = 4 and s = 6
            new IntersectionCall("outside", OFF_ORIGIN, SLANT, new double[] {4, -1, 4.5}, 1),
            // the line passes at distance 3 from the centre
            new IntersectionCall("miss", OFF_ORIGIN, SLANT, new double[] {4, 2, 4.5}, 1),
            // roots s = -4 and s = -6
            new IntersectionCall("away", OFF_ORIGIN, new double[] {-0.6, 0, -0.8}, new double[] {4, -1, 4.5}, 1),
            new IntersectionCall("behind", ORIGIN, ALONG_Z, new double[] {0, 0, -5}, 1),
            // b^2 - 4ac = 100 - 100 = 0 exactly: one root, s = 5
            new IntersectionCall("graze", ORIGIN, ALONG_Z, new double[] {0, 1, 5}, 1),
            // roots s = -1.5 and s = 2.5
            new IntersectionCall("inside", ORIGIN, ALONG_Z, new double[] {0, 0, 0.5}, 2),
            // roots s = 0 and s = 2
            new IntersectionCall("surface", ORIGIN, ALONG_Z, new double[] {0, 0, 1}, 1));

    /**
     * Shadings: the ambient term alone (intensity 0) with each channel on its own; the light along
     * the normal at distance 1 and 2; behind the surface (N.L &lt; 0); to the side, so that R points
     * away from the camera (R.V = -1); at an angle; and with the camera at distance 2.
     */
    public static final List<IlluminationCall> ILLUMINATIONS = List.of(
            new IlluminationCall("ambient", new double[] {0.5, 0.75, 0.25}, DARK, near(new double[] {0.2, 0.4, 0.6}),
                    NEAR_POINT, TOWARDS_CAMERA),
            new IlluminationCall("red", WHITE, DARK, near(new double[] {1, 0, 0}), NEAR_POINT, TOWARDS_CAMERA),
            new IlluminationCall("green", WHITE, DARK, near(new double[] {0, 1, 0}), NEAR_POINT, TOWARDS_CAMERA),
            new IlluminationCall("blue", WHITE, DARK, near(new double[] {0, 0, 1}), NEAR_POINT, TOWARDS_CAMERA),
            new IlluminationCall("near", BLACK, white(ORIGIN), near(NO_GREEN), NEAR_POINT, TOWARDS_CAMERA),
            new IlluminationCall("far", BLACK, white(new double[] {0, 0, -1}), near(NO_GREEN), NEAR_POINT,
                    TOWARDS_CAMERA),
            new IlluminationCall("light-behind", BLACK, white(new double[] {0, 0, 3}), near(NO_GREEN), NEAR_POINT,
                    TOWARDS_CAMERA),
            // P = (0.6, 0, 0.8) at distance 1 from the camera, N = (1, 0, 0), L = (0.6, 0, -0.8): R = -V
            new IlluminationCall("side", BLACK, white(new double[] {1.2, 0, 0}),
                    new SphereInput(new double[] {-0.4, 0, 0.8}, 1, Material.course(NO_GREEN)),
                    new double[] {0.6, 0, 0.8}, new double[] {1, 0, 0}),
            // L = (0.6, 0, -0.8): N.L = R.V = 0.8
            new IlluminationCall("oblique", BLACK, white(new double[] {0.6, 0, 0.2}), near(NO_GREEN), NEAR_POINT,
                    TOWARDS_CAMERA),
            // the camera at distance 2 from P, the light at distance 1 along the normal
            new IlluminationCall("camera-far", BLACK, white(new double[] {0, 0, 1}),
                    new SphereInput(new double[] {0, 0, 3}, 1, Material.course(NO_GREEN)), new double[] {0, 0, 2},
                    TOWARDS_CAMERA));

    /** A white light at {@code position} of intensity 4 pi: I = 1 at distance 1. */
    private static LightInput white(double[] position) {
        return new LightInput(position, WHITE, FOUR_PI);
    }

    /** The sphere of centre (0, 0, 2) and radius 1, of {@code colour} and the course's coefficients. */
    private static SphereInput near(double[] colour) {
        return new SphereInput(NEAR_CENTRE, 1, Material.course(colour));
    }

    /** The unit vectors of round components (0, 1), (0.6, 0.8) and (0.48, 0.6, 0.64), any order and signs. */
    private static final double[][] ROUND_UNITS = {{1, 0, 0}, {0.6, 0.8, 0}, {0.48, 0.6, 0.64}};

    /** How many random inputs each method is called on. */
    public static final int RANDOM_COUNT = 1000;
    /** The seed of the random inputs: fixed, so that every grade asks the same questions. */
    private static final long SEED = 20261202L;

    /**
     * Random rays and spheres in round numbers: an origin and a centre of whole coordinates, a
     * direction of whole coordinates (rarely a unit vector), a radius in halves. The origin is
     * always outside the sphere, by a margin, and the ray never nearly grazes it (the discriminant
     * is at least a thousandth of b^2 from 0): those cases are among the edge cases above, and the
     * course's scenes cannot show them.
     */
    public static final List<IntersectionCall> RANDOM_INTERSECTIONS = randomIntersections();

    /**
     * Random shadings in round numbers: coloured ambient and point lights, a coloured sphere, k_d
     * and k_s in tenths, n a whole number, P of whole coordinates (never the camera's origin), N a
     * unit vector, and a light whole steps away from P with intensity a whole multiple of 4 pi.
     */
    public static final List<IlluminationCall> RANDOM_ILLUMINATIONS = randomIlluminations();

    private static List<IntersectionCall> randomIntersections() {
        SplittableRandom random = new SplittableRandom(SEED);
        List<IntersectionCall> calls = new ArrayList<>();
        while (calls.size() < RANDOM_COUNT) {
            double[] origin = whole(random, 4), direction = whole(random, 3);
            double t = random.nextInt(-3, 7), radius = random.nextInt(1, 7) / 2.0;
            double[] centre = new double[3];
            for (int i = 0; i < 3; i++) {
                centre[i] = origin[i] + t * direction[i] + random.nextInt(-2, 3);
            }
            double a = dot(direction, direction);
            double[] oc = {origin[0] - centre[0], origin[1] - centre[1], origin[2] - centre[2]};
            double b = 2 * dot(direction, oc), c = dot(oc, oc) - radius * radius;
            double discriminant = b * b - 4 * a * c;
            if (a > 0 && c >= 0.25 && Math.abs(discriminant) >= 1e-3 * b * b) {
                calls.add(new IntersectionCall("ray" + calls.size(), origin, direction, centre, radius));
            }
        }
        return List.copyOf(calls);
    }

    private static List<IlluminationCall> randomIlluminations() {
        SplittableRandom random = new SplittableRandom(SEED + 1);
        List<IlluminationCall> calls = new ArrayList<>();
        while (calls.size() < RANDOM_COUNT) {
            double[] point = whole(random, 4), offset = whole(random, 2);
            double[] normal = unit(random);
            if (dot(point, point) == 0 || dot(offset, offset) == 0) {
                continue;
            }
            double[] light = {point[0] + offset[0], point[1] + offset[1], point[2] + offset[2]};
            double[] centre = {point[0] - normal[0], point[1] - normal[1], point[2] - normal[2]};
            // In the order the random numbers were always drawn: ambient, light, material.
            double[] ambient = tenths(random, 0, 5);
            LightInput shining = new LightInput(light, tenths(random, 2, 10), 4 * Math.PI * random.nextInt(1, 5));
            Material material = new Material(tenths(random, 0, 10), random.nextInt(1, 11) / 10.0,
                    random.nextInt(1, 11) / 10.0, random.nextInt(1, 31));
            calls.add(new IlluminationCall("shade" + calls.size(), ambient, shining,
                    new SphereInput(centre, 1, material), point, normal));
        }
        return List.copyOf(calls);
    }

    /**
     * The file, beside the harness's jar, of inputs the grader chose for one run (the rays of an
     * image's differing pixels, and the shadings there): when it is there, the harness calls the
     * methods on those alone. It is written by the grader into a folder the student's code can
     * only read.
     */
    public static final String CHOSEN_FILE = "inputs";

    /** Inputs the grader chose, each named as its answer will be. */
    public record Chosen(List<IntersectionCall> intersections, List<IlluminationCall> illuminations) {

        /** One line a call: "ray NAME" and 10 numbers, or "shade NAME" and 26, each as Double.toString writes it. */
        public String text() {
            StringBuilder text = new StringBuilder();
            for (IntersectionCall call : intersections) {
                text.append("ray ").append(call.name());
                append(text, call.origin(), call.direction(), call.centre(), new double[] {call.radius()});
                text.append('\n');
            }
            for (IlluminationCall call : illuminations) {
                LightInput light = call.light();
                SphereInput sphere = call.sphere();
                Material material = sphere.material();
                text.append("shade ").append(call.name());
                append(text, call.ambient(), light.position(), light.colour(), new double[] {light.intensity()},
                        sphere.centre(), new double[] {sphere.radius()}, material.colour(),
                        new double[] {material.kD(), material.kS(), material.n()}, call.point(), call.normal());
                text.append('\n');
            }
            return text.toString();
        }

        private static void append(StringBuilder text, double[]... parts) {
            for (double[] part : parts) {
                for (double x : part) {
                    text.append(' ').append(x);
                }
            }
        }

        /** The inputs of {@link #text}; a line of another form is left out. */
        public static Chosen read(String text) {
            List<IntersectionCall> rays = new ArrayList<>();
            List<IlluminationCall> shadings = new ArrayList<>();
            for (String line : text.split("\n")) {
                String[] words = line.split(" ");
                try {
                    if (words.length == 12 && words[0].equals("ray")) {
                        double[] n = numbers(words);
                        rays.add(new IntersectionCall(words[1], part(n, 0), part(n, 3), part(n, 6), n[9]));
                    } else if (words.length == 28 && words[0].equals("shade")) {
                        double[] n = numbers(words);
                        shadings.add(new IlluminationCall(words[1], part(n, 0),
                                new LightInput(part(n, 3), part(n, 6), n[9]), new SphereInput(part(n, 10), n[13],
                                new Material(part(n, 14), n[17], n[18], n[19])), part(n, 20), part(n, 23)));
                    }
                } catch (NumberFormatException e) {
                    // not a line of text(): left out
                }
            }
            return new Chosen(List.copyOf(rays), List.copyOf(shadings));
        }

        private static double[] numbers(String[] words) {
            double[] n = new double[words.length - 2];
            for (int i = 0; i < n.length; i++) {
                n[i] = Double.parseDouble(words[i + 2]);
            }
            return n;
        }

        private static double[] part(double[] n, int from) {
            return new double[] {n[from], n[from + 1], n[from + 2]};
        }
    }

    /** A vector of whole coordinates from -bound to bound. */
    private static double[] whole(SplittableRandom random, int bound) {
        return new double[] {random.nextInt(-bound, bound + 1), random.nextInt(-bound, bound + 1),
                random.nextInt(-bound, bound + 1)};
    }

    /** A colour of tenths from from/10 to to/10 in each channel. */
    private static double[] tenths(SplittableRandom random, int from, int to) {
        return new double[] {random.nextInt(from, to + 1) / 10.0, random.nextInt(from, to + 1) / 10.0,
                random.nextInt(from, to + 1) / 10.0};
    }

    /** A unit normal: half the time one of round components, else a whole vector normalised. */
    private static double[] unit(SplittableRandom random) {
        double[] v;
        if (random.nextBoolean()) {
            double[] round = ROUND_UNITS[random.nextInt(ROUND_UNITS.length)];
            int shift = random.nextInt(3);
            v = new double[3];
            for (int i = 0; i < 3; i++) {
                v[i] = round[(i + shift) % 3] * (random.nextBoolean() ? 1 : -1) + 0.0;
            }
            return v;
        }
        do {
            v = whole(random, 3);
        } while (dot(v, v) == 0);
        double length = Math.sqrt(dot(v, v));
        return new double[] {v[0] / length, v[1] / length, v[2] / length};
    }

    private static double dot(double[] u, double[] v) {
        return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    }
}
