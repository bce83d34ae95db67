package gfx.tick1.command.shared.behaviour;

import static gfx.tick1.command.shared.behaviour.Variant.AMBIENT_DIFFUSE;
import static gfx.tick1.command.shared.behaviour.Variant.AMBIENT_ONLY;
import static gfx.tick1.command.shared.behaviour.Variant.AMBIENT_WITHOUT_C_DIFF;
import static gfx.tick1.command.shared.behaviour.Variant.BACKGROUND_ONLY;
import static gfx.tick1.command.shared.behaviour.Variant.COLOUR_OVER_255;
import static gfx.tick1.command.shared.behaviour.Variant.COLOUR_TIMES_255;
import static gfx.tick1.command.shared.behaviour.Variant.DIFFUSE_WITHOUT_C_DIFF;
import static gfx.tick1.command.shared.behaviour.Variant.DISTANCE_ALWAYS_S1;
import static gfx.tick1.command.shared.behaviour.Variant.DIVIDED_BY_2_TIMES_A;
import static gfx.tick1.command.shared.behaviour.Variant.FALL_OFF_WITHOUT_4PI;
import static gfx.tick1.command.shared.behaviour.Variant.FAR_ROOT;
import static gfx.tick1.command.shared.behaviour.Variant.FLAT_COLOUR;
import static gfx.tick1.command.shared.behaviour.Variant.HANDOUT_SIX_STEPS;
import static gfx.tick1.command.shared.behaviour.Variant.HIGHLIGHT_COLOURED;
import static gfx.tick1.command.shared.behaviour.Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT;
import static gfx.tick1.command.shared.behaviour.Variant.KD_SWAPPED_WITH_KS;
import static gfx.tick1.command.shared.behaviour.Variant.L_FROM_THE_LIGHT;
import static gfx.tick1.command.shared.behaviour.Variant.NORMAL_NOT_NORMALISED;
import static gfx.tick1.command.shared.behaviour.Variant.NO_AMBIENT;
import static gfx.tick1.command.shared.behaviour.Variant.NO_FALL_OFF;
import static gfx.tick1.command.shared.behaviour.Variant.ROOTS_ACCEPTED_AT_ZERO;
import static gfx.tick1.command.shared.behaviour.Variant.ROOTS_IN_FLOAT;
import static gfx.tick1.command.shared.behaviour.Variant.R_WRONG_WAY;
import static gfx.tick1.command.shared.behaviour.Variant.SPECULAR_WITHOUT_I;
import static gfx.tick1.command.shared.behaviour.Variant.UNCHECKED_NEGATIVE_SQUARE_ROOT;
import static gfx.tick1.command.shared.behaviour.Variant.UNCLAMPED_N_DOT_L;
import static gfx.tick1.command.shared.behaviour.Variant.UNCLAMPED_R_DOT_V;
import static gfx.tick1.command.shared.behaviour.Variant.UNNORMALISED_L_V;
import static gfx.tick1.command.shared.behaviour.Variant.V_AWAY_FROM_CAMERA;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.Renderer;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.Set;

/**
 * The catalogue's entries as runnable models of the two methods a student writes:
 * {@code Sphere.intersectionWith} and {@code Renderer.illuminate}, written in the order of the
 * reference's code with each entry's change at the line where that slip happens; with several,
 * the slips together. With no slip of a method (no entry, or {@link Variant#CORRECT}) its model
 * calls the reference's own method (the engine's {@code Sphere.intersectionWith} and
 * {@code Renderer.illuminate}), so that the correct answers are ours by construction, not by a
 * second copy of our code. {@code VariantRenderer} renders images with them, and {@code grade} and {@code diff}
 * compare a student's answers with theirs.
 */
public final class Models {

    /** The colour of the spheres intersectionWith is asked about: it plays no part in the answer. */
    private static final Vector3 ANY_COLOUR = new Vector3(1);

    /**
     * The reference's illuminate, private as the starter's is (the reference's Renderer differs from
     * the starter kit's only inside its TODOs), so reached as the harness reaches the student's.
     */
    private static final Method REFERENCE_ILLUMINATE = referenceIlluminate();
    /** A renderer to call it on: illuminate reads nothing of the image's size. */
    private static final Renderer REFERENCE = new Renderer(1, 1);

    private Models() {
    }

    private static Method referenceIlluminate() {
        try {
            Method illuminate = Renderer.class.getDeclaredMethod("illuminate", Scene.class, Sphere.class,
                    Vector3.class, Vector3.class);
            illuminate.setAccessible(true);
            return illuminate;
        } catch (NoSuchMethodException e) {
            throw new IllegalStateException("the reference's Renderer has no illuminate(Scene, Sphere, Vector3, "
                    + "Vector3)", e);
        }
    }

    /** A sphere of the reference with the Phong coefficients of a shading, which the course's fix. */
    private static final class ShadedSphere extends Sphere {
        private final double kD, kS, n;

        ShadedSphere(Shading at) {
            super(at.point().subtract(at.normal()), 1, at.surface().colour());
            this.kD = at.surface().kD();
            this.kS = at.surface().kS();
            this.n = at.surface().n();
        }

        @Override
        public double getPhong_kD() {
            return kD;
        }

        @Override
        public double getPhong_kS() {
            return kS;
        }

        @Override
        public double getPhong_n() {
            return n;
        }
    }

    /** What intersectionWith returns for a hit: the distance s, the point and the normal. */
    public record Hit(double distance, Vector3 point, Vector3 normal) {
    }

    /** A sphere's surface as illuminate reads it: its colour C_diff and Phong coefficients k_d, k_s and n. */
    public record Surface(Vector3 colour, double kD, double kS, double n) {
    }

    /**
     * What illuminate is given: the scene's ambient light I_a and point light, the sphere's surface,
     * the point P and the normal N.
     */
    public record Shading(Vector3 ambientLight, PointLight light, Surface surface, Vector3 point, Vector3 normal) {
    }

    /**
     * Sphere.intersectionWith for the ray O + s D and the sphere of centre C and radius r, with
     * the slips of {@code variants}: the hit, or null for the empty RaycastHit.
     */
    public static Hit intersect(Vector3 O, Vector3 D, Vector3 C, double r, Set<Variant> variants) {
        if (noSlipOf(variants, Variant.Method.INTERSECTION_WITH)) {
            RaycastHit hit = new Sphere(C, r, ANY_COLOUR).intersectionWith(new Ray(O, D));
            return hit.getObjectHit() == null ? null : new Hit(hit.getDistance(), hit.getLocation(), hit.getNormal());
        }
        if (variants.contains(BACKGROUND_ONLY)) {
            return null;
        }
        double a = D.dot(D);
        double b = 2 * D.dot(O.subtract(C));
        double c = O.subtract(C).dot(O.subtract(C)) - Math.pow(r, 2);
        double discriminant = b * b - 4 * a * c;
        if (discriminant < 0 && !variants.contains(UNCHECKED_NEGATIVE_SQUARE_ROOT)) {
            return null;
        }
        double s1, s2;
        if (variants.contains(DIVIDED_BY_2_TIMES_A)) {
            s1 = (-b - Math.sqrt(discriminant)) / 2 * a;
            s2 = (-b + Math.sqrt(discriminant)) / 2 * a;
        } else {
            s1 = (-b - Math.sqrt(discriminant)) / (2 * a);
            s2 = (-b + Math.sqrt(discriminant)) / (2 * a);
        }
        if (variants.contains(ROOTS_IN_FLOAT)) {
            s1 = (float) s1;
            s2 = (float) s2;
        }
        double s = chosenRoot(s1, s2, variants);
        boolean hit = variants.contains(ROOTS_ACCEPTED_AT_ZERO) ? s >= 0 : s > 0; // false for NaN: a miss
        if (!hit) {
            return null;
        }
        Vector3 point = O.add(D.scale(s));
        Vector3 outward = point.subtract(C);
        return new Hit(variants.contains(DISTANCE_ALWAYS_S1) ? s1 : s, point,
                variants.contains(NORMAL_NOT_NORMALISED) ? outward : outward.normalised());
    }

    /** Steps 4 to 6: the root taken, NaN for none. */
    private static double chosenRoot(double s1, double s2, Set<Variant> variants) {
        if (variants.contains(FAR_ROOT)) {
            return s2;
        }
        if (variants.contains(ROOTS_ACCEPTED_AT_ZERO)) {
            return s1 >= 0 ? s1 : s2;
        }
        if (variants.contains(HANDOUT_SIX_STEPS)) {
            return s1 > 0 && s1 < s2 ? s1 : s2 > 0 && s2 < s1 ? s2 : Double.NaN;
        }
        if (variants.contains(HIT_REJECTED_ON_A_NEGATIVE_ROOT) && (s1 < 0 || s2 < 0)) {
            return Double.NaN;
        }
        return s1 > 0 ? s1 : s2;
    }

    /** Renderer.illuminate at {@code at}, with the slips of {@code variants}. */
    public static Vector3 illuminate(Shading at, Set<Variant> variants) {
        if (noSlipOf(variants, Variant.Method.ILLUMINATE) && at.light() != null) {
            return reference(at);
        }
        Vector3 I_a = at.ambientLight();
        Vector3 C_diff = at.surface().colour();
        if (variants.contains(FLAT_COLOUR)) {
            return C_diff;
        }
        Vector3 ambient = variants.contains(AMBIENT_WITHOUT_C_DIFF) ? I_a : C_diff.scale(I_a);

        PointLight light = at.light();
        if (light == null || variants.contains(AMBIENT_ONLY)) {
            return variants.contains(NO_AMBIENT) ? new Vector3(0) : ambient;
        }
        Vector3 P = at.point(), N = at.normal();
        double distanceToLight = light.getPosition().subtract(P).magnitude();
        Vector3 I = illumination(light, distanceToLight, variants);
        Vector3 C_spec = variants.contains(HIGHLIGHT_COLOURED) ? C_diff : new Vector3(1);

        boolean swapped = variants.contains(KD_SWAPPED_WITH_KS);
        double k_d = swapped ? at.surface().kS() : at.surface().kD();
        double k_s = swapped ? at.surface().kD() : at.surface().kS();
        double n = at.surface().n();

        Vector3 toLight = variants.contains(L_FROM_THE_LIGHT) ? P.subtract(light.getPosition())
                : light.getPosition().subtract(P);
        Vector3 L = variants.contains(UNNORMALISED_L_V) ? toLight : toLight.normalised();
        Vector3 V = variants.contains(UNNORMALISED_L_V) ? P.scale(-1)
                : variants.contains(V_AWAY_FROM_CAMERA) ? P.normalised() // from the camera at the origin towards P
                : P.scale(-1).normalised();
        Vector3 R = variants.contains(R_WRONG_WAY) ? N.reflectIn(L) : L.reflectIn(N);

        double NdotL = N.dot(L);
        double RdotV = R.dot(V);
        double diffuseFactor = variants.contains(UNCLAMPED_N_DOT_L) ? NdotL : Math.max(0, NdotL);
        double specularBase = variants.contains(UNCLAMPED_R_DOT_V) ? RdotV : Math.max(0, RdotV);

        Vector3 diffuse = variants.contains(DIFFUSE_WITHOUT_C_DIFF) ? I.scale(k_d * diffuseFactor)
                : C_diff.scale(I).scale(k_d * diffuseFactor);
        if (variants.contains(AMBIENT_DIFFUSE)) {
            return variants.contains(NO_AMBIENT) ? diffuse : ambient.add(diffuse);
        }
        Vector3 specular = variants.contains(SPECULAR_WITHOUT_I) ? C_spec.scale(k_s * Math.pow(specularBase, n))
                : C_spec.scale(I).scale(k_s * Math.pow(specularBase, n));
        Vector3 sum = variants.contains(NO_AMBIENT) ? diffuse.add(specular) : ambient.add(diffuse).add(specular);
        return variants.contains(COLOUR_TIMES_255) ? sum.scale(255)
                : variants.contains(COLOUR_OVER_255) ? sum.scale(1.0 / 255) : sum;
    }

    /** Whether none of {@code variants} is a slip of {@code method}: its model is then the reference's. */
    private static boolean noSlipOf(Set<Variant> variants, Variant.Method method) {
        for (Variant variant : variants) {
            if (variant.method() == method) {
                return false;
            }
        }
        return true;
    }

    /** The reference's illuminate at {@code at}. */
    private static Vector3 reference(Shading at) {
        Scene scene = new Scene();
        scene.setAmbientLight(at.ambientLight());
        scene.setPointLight(at.light());
        try {
            return (Vector3) REFERENCE_ILLUMINATE.invoke(REFERENCE, scene, new ShadedSphere(at), at.point(),
                    at.normal());
        } catch (IllegalAccessException | InvocationTargetException e) {
            throw new IllegalStateException("the reference's illuminate could not be called", e);
        }
    }

    /** I = light colour * intensity / (4 pi d^2), or one of the two ways of getting it wrong. */
    private static Vector3 illumination(PointLight light, double distance, Set<Variant> variants) {
        if (variants.contains(NO_FALL_OFF)) {
            return light.getColour().scale(light.getIntensity() / (Math.PI * 4));
        }
        if (variants.contains(FALL_OFF_WITHOUT_4PI)) {
            return light.getColour().scale(light.getIntensity() / Math.pow(distance, 2));
        }
        return light.getIlluminationAt(distance);
    }
}
