package gfx.tick1.engine.fast;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.RobustIntersection;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.util.List;

/**
 * A scene laid out as arrays of doubles for the fast kernel: one entry per sphere, in file order.
 *
 * <p>Every camera ray starts at the origin O = 0, so the handout's per-sphere terms that do not
 * depend on the ray are computed once here, with the same operations the readable code performs
 * per ray (f = O - C = 0 - C; c = f.f - r^2), which gives the same bits.
 */
final class FlatScene {

    final int size;
    final Intersection intersection;
    /** The constant term of the quadratic, f.f - r^2. */
    final double[] c;
    /** Per sphere, f = O - C with O = 0 and the robust method's other ray-independent terms. */
    final RobustIntersection.Offset[] offsets;
    final double[] cx, cy, cz, radius;
    /** C_diff. */
    final double[] red, green, blue;
    /**
     * The Phong coefficients k_d, k_s and n, read from each {@link Sphere} as the readable
     * Renderer reads them, so that the two cannot differ.
     */
    final double[] kD, kS, n;
    final double ambientRed, ambientGreen, ambientBlue;
    final boolean lit;
    final double lightX, lightY, lightZ, lightRed, lightGreen, lightBlue, intensity;

    FlatScene(Scene scene, Intersection intersection) {
        this.intersection = intersection;
        List<Sphere> spheres = scene.getObjects();
        size = spheres.size();
        c = new double[size];
        offsets = new RobustIntersection.Offset[size];
        cx = new double[size];
        cy = new double[size];
        cz = new double[size];
        radius = new double[size];
        red = new double[size];
        green = new double[size];
        blue = new double[size];
        kD = new double[size];
        kS = new double[size];
        n = new double[size];
        for (int i = 0; i < size; i++) {
            Sphere sphere = spheres.get(i);
            Vector3 centre = SphereGeometry.centre(sphere);
            cx[i] = centre.x;
            cy[i] = centre.y;
            cz[i] = centre.z;
            radius[i] = SphereGeometry.radius(sphere);
            // f = O - C for O = 0.
            double fx = 0 - centre.x, fy = 0 - centre.y, fz = 0 - centre.z;
            c[i] = (fx * fx + fy * fy + fz * fz) - Math.pow(radius[i], 2);
            offsets[i] = RobustIntersection.Offset.of(fx, fy, fz, radius[i]);
            red[i] = sphere.getColour().x;
            green[i] = sphere.getColour().y;
            blue[i] = sphere.getColour().z;
            kD[i] = sphere.getPhong_kD();
            kS[i] = sphere.getPhong_kS();
            n[i] = sphere.getPhong_n();
        }
        Vector3 ambient = scene.getAmbientLighting();
        ambientRed = ambient.x;
        ambientGreen = ambient.y;
        ambientBlue = ambient.z;
        PointLight light = scene.getPointLight();
        lit = light != null;
        lightX = lit ? light.getPosition().x : 0;
        lightY = lit ? light.getPosition().y : 0;
        lightZ = lit ? light.getPosition().z : 0;
        lightRed = lit ? light.getColour().x : 0;
        lightGreen = lit ? light.getColour().y : 0;
        lightBlue = lit ? light.getColour().z : 0;
        intensity = lit ? light.getIntensity() : 0;
    }

    /**
     * The nearest root s &gt; 0 of sphere i along the unit direction D from the origin, or
     * +infinity, as {@link Intersection#find} decides it: for {@link Intersection#HANDOUT} the
     * handout's quadratic; otherwise {@link RobustIntersection#nearestRoot}, the same decision
     * code the readable path runs, which defers to the handout's quadratic where that is accurate.
     * a = D.D is passed in because it is the same for every sphere.
     */
    double nearestRoot(int i, double dx, double dy, double dz, double a) {
        if (intersection == Intersection.HANDOUT) {
            return handoutRoot(i, dx, dy, dz, a);
        }
        double s = RobustIntersection.nearestRoot(dx, dy, dz, a, offsets[i], intersection == Intersection.ROBUST);
        if (s == RobustIntersection.HANDOUT_IS_ACCURATE) {
            return handoutRoot(i, dx, dy, dz, a);
        }
        return s > 0 ? s : Double.POSITIVE_INFINITY;
    }

    /**
     * The handout's quadratic, term for term as {@code Sphere.intersectionWith} computes it:
     * the nearest root s &gt; 0, or +infinity.
     */
    private double handoutRoot(int i, double dx, double dy, double dz, double a) {
        double b = 2 * RobustIntersection.roughBeta(dx, dy, dz, offsets[i]);
        double discriminant = b * b - 4 * a * c[i];
        if (discriminant < 0) {
            return Double.POSITIVE_INFINITY;
        }
        double root = Math.sqrt(discriminant);
        double s1 = (-b - root) / (2 * a);
        double s2 = (-b + root) / (2 * a);
        double s = s1 > 0 ? s1 : s2;
        return s > 0 ? s : Double.POSITIVE_INFINITY;
    }
}
