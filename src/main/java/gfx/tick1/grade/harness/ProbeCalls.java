package gfx.tick1.grade.harness;

import java.util.List;

/**
 * The fixed inputs on which the harness calls a student's {@code Sphere.intersectionWith} and
 * {@code Renderer.illuminate}. Each call has a name; the harness reports what it returned by that
 * name, and the grader, which holds the same inputs, decides what the answers mean. The inputs are
 * chosen so that the answers are round numbers: the rays of the intersections have unit
 * directions, the lights of the illuminations are at distance 1 or 2 with intensity 4 pi (so that
 * I = 1 or 1/4), and the camera is at distance 1 or 2 from the point shaded.
 */
public final class ProbeCalls {

    private ProbeCalls() {
    }

    /** A ray (origin O, direction D) and a sphere (centre C, radius r) for intersectionWith. */
    public record Intersection(String name, double[] origin, double[] direction, double[] centre, double radius) {
    }

    /**
     * A scene (ambient light, one point light of a colour and intensity), a sphere (centre, radius,
     * colour C_diff), and the point P and unit normal N to shade on it, for illuminate.
     */
    public record Illumination(String name, double[] ambient, double[] light, double[] lightColour,
            double intensity, double[] centre, double radius, double[] colour, double[] point, double[] normal) {
    }

    private static final double FOUR_PI = 4 * Math.PI;
    private static final double[] ORIGIN = {0, 0, 0}, ALONG_Z = {0, 0, 1}, WHITE = {1, 1, 1}, BLACK = {0, 0, 0};
    /** An origin off the axes and a unit direction, so that code that assumes O = 0 shows it. */
    private static final double[] OFF_ORIGIN = {1, -1, 0.5}, SLANT = {0.6, 0, 0.8};
    /** On the sphere of centre (0, 0, 2) and radius 1, the point nearest the camera, facing it. */
    private static final double[] NEAR_POINT = {0, 0, 1}, TOWARDS_CAMERA = {0, 0, -1}, NEAR_CENTRE = {0, 0, 2};
    /** A colour with no green: green is then the specular term alone, red minus green the diffuse. */
    private static final double[] NO_GREEN = {0.5, 0, 0.25};

    /** Rays and spheres: a hit, a miss, a graze, a ray pointing away, a sphere behind, inside, on the surface. */
    public static final List<Intersection> INTERSECTIONS = List.of(
            // C = O + 5 D: roots s = 4 and s = 6
            new Intersection("outside", OFF_ORIGIN, SLANT, new double[] {4, -1, 4.5}, 1),
            // the line passes at distance 3 from the centre
            new Intersection("miss", OFF_ORIGIN, SLANT, new double[] {4, 2, 4.5}, 1),
            // roots s = -4 and s = -6
            new Intersection("away", OFF_ORIGIN, new double[] {-0.6, 0, -0.8}, new double[] {4, -1, 4.5}, 1),
            new Intersection("behind", ORIGIN, ALONG_Z, new double[] {0, 0, -5}, 1),
            // b^2 - 4ac = 100 - 100 = 0 exactly: one root, s = 5
            new Intersection("graze", ORIGIN, ALONG_Z, new double[] {0, 1, 5}, 1),
            // roots s = -1.5 and s = 2.5
            new Intersection("inside", ORIGIN, ALONG_Z, new double[] {0, 0, 0.5}, 2),
            // roots s = 0 and s = 2
            new Intersection("surface", ORIGIN, ALONG_Z, new double[] {0, 0, 1}, 1));

    /**
     * Shadings: the ambient term alone (intensity 0) with each channel on its own; the light along
     * the normal at distance 1 and 2; behind the surface (N.L &lt; 0); to the side, so that R points
     * away from the camera (R.V = -1); at an angle; and with the camera at distance 2.
     */
    public static final List<Illumination> ILLUMINATIONS = List.of(
            new Illumination("ambient", new double[] {0.5, 0.75, 0.25}, new double[] {0, 0, 5}, WHITE, 0,
                    NEAR_CENTRE, 1, new double[] {0.2, 0.4, 0.6}, NEAR_POINT, TOWARDS_CAMERA),
            new Illumination("red", WHITE, new double[] {0, 0, 5}, WHITE, 0, NEAR_CENTRE, 1,
                    new double[] {1, 0, 0}, NEAR_POINT, TOWARDS_CAMERA),
            new Illumination("green", WHITE, new double[] {0, 0, 5}, WHITE, 0, NEAR_CENTRE, 1,
                    new double[] {0, 1, 0}, NEAR_POINT, TOWARDS_CAMERA),
            new Illumination("blue", WHITE, new double[] {0, 0, 5}, WHITE, 0, NEAR_CENTRE, 1,
                    new double[] {0, 0, 1}, NEAR_POINT, TOWARDS_CAMERA),
            new Illumination("near", BLACK, ORIGIN, WHITE, FOUR_PI, NEAR_CENTRE, 1, NO_GREEN, NEAR_POINT,
                    TOWARDS_CAMERA),
            new Illumination("far", BLACK, new double[] {0, 0, -1}, WHITE, FOUR_PI, NEAR_CENTRE, 1, NO_GREEN,
                    NEAR_POINT, TOWARDS_CAMERA),
            new Illumination("light-behind", BLACK, new double[] {0, 0, 3}, WHITE, FOUR_PI, NEAR_CENTRE, 1, NO_GREEN,
                    NEAR_POINT, TOWARDS_CAMERA),
            // P = (0.6, 0, 0.8) at distance 1 from the camera, N = (1, 0, 0), L = (0.6, 0, -0.8): R = -V
            new Illumination("side", BLACK, new double[] {1.2, 0, 0}, WHITE, FOUR_PI, new double[] {-0.4, 0, 0.8}, 1,
                    NO_GREEN, new double[] {0.6, 0, 0.8}, new double[] {1, 0, 0}),
            // L = (0.6, 0, -0.8): N.L = R.V = 0.8
            new Illumination("oblique", BLACK, new double[] {0.6, 0, 0.2}, WHITE, FOUR_PI, NEAR_CENTRE, 1, NO_GREEN,
                    NEAR_POINT, TOWARDS_CAMERA),
            // the camera at distance 2 from P, the light at distance 1 along the normal
            new Illumination("camera-far", BLACK, new double[] {0, 0, 1}, WHITE, FOUR_PI, new double[] {0, 0, 3}, 1,
                    NO_GREEN, new double[] {0, 0, 2}, TOWARDS_CAMERA));
}
