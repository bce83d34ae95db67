package gfx.tick1.engine.render;

import gfx.tick1.engine.math.DoubleDouble;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.awt.image.BufferedImage;
import java.math.BigDecimal;
import java.util.List;
import java.util.stream.IntStream;

/**
 * The image a scene would have if every step after the camera were computed in exact arithmetic:
 * the yardstick the tests and the benchmark measure the double-precision renderers against.
 *
 * <p>Its inputs are the same doubles the renderer sees: the scene as loaded, and each pixel's ray
 * exactly as {@link Camera#castRay} rounds it (that rounding is part of the spec, and a ray that
 * grazes a sphere within an ulp of its direction would otherwise decide hit or miss by chance).
 * From there it follows the spec's formulas literally, without any of the robust renderer's care,
 * in {@link DoubleDouble} arithmetic (106 bits; c = |O - C|^2 - r^2 exactly): the quadratic, the normal
 * normalise(P - C), and Phong shading, truncating each channel of the exact colour. Cancellation
 * that costs a double all its 53 bits still leaves this about 50, which is far more than an 8-bit
 * pixel needs; {@code TruthRendererTest} checks it against closed-form answers and against
 * {@link java.math.BigDecimal} arithmetic.
 *
 * <p>It is slow, many times the double renderer, and meant to be: each operation is a few on doubles.
 */
public final class TruthRenderer {

    private static final DoubleDouble TWO = DoubleDouble.of(2);

    private final int width, height;

    public TruthRenderer(int width, int height) {
        this.width = width;
        this.height = height;
    }

    /** The exact image, one {@link Camera#castRay} per pixel, as {@link Renderer#render} lays it out. */
    public BufferedImage render(Scene scene) {
        Camera camera = new Camera(width, height);
        // Every camera ray starts at the same point, so each sphere's c = |O - C|^2 - r^2, the
        // costly BigDecimal part, is the same for all of them: computed once here.
        Vector3 origin = camera.castRay(0, 0).getOrigin();
        DoubleDouble[] c = scene.getObjects().stream()
                .map(sphere -> exactC(origin, SphereGeometry.centre(sphere), SphereGeometry.radius(sphere)))
                .toArray(DoubleDouble[]::new);
        int[] pixels = new int[width * height];
        IntStream.range(0, height).parallel().forEach(y -> {
            for (int x = 0; x < width; x++) {
                pixels[y * width + x] = toRGB(trace(scene, camera.castRay(x, y), c));
            }
        });
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, pixels, 0, width);
        return image;
    }

    /** The exact colour seen along the ray, before clamping. */
    public Vec trace(Scene scene, Ray ray) {
        DoubleDouble[] c = scene.getObjects().stream()
                .map(sphere -> exactC(ray.getOrigin(), SphereGeometry.centre(sphere), SphereGeometry.radius(sphere)))
                .toArray(DoubleDouble[]::new);
        return trace(scene, ray, c);
    }

    /** As above, with each sphere's c for this ray's origin computed beforehand, in scene order. */
    private static Vec trace(Scene scene, Ray ray, DoubleDouble[] c) {
        Vec O = Vec.of(ray.getOrigin());
        Vec D = Vec.of(ray.getDirection());
        List<Sphere> spheres = scene.getObjects();
        Sphere closest = null;
        DoubleDouble closestDistance = null;
        for (int i = 0; i < spheres.size(); i++) {
            Sphere sphere = spheres.get(i);
            DoubleDouble s = hitDistance(sphere, ray, c[i]);
            // Strictly closer, so that the earlier sphere wins an exact tie.
            if (s != null && (closestDistance == null || s.compareTo(closestDistance) < 0)) {
                closest = sphere;
                closestDistance = s;
            }
        }
        if (closest == null) {
            return Vec.of(ReferenceRenderer.BACKGROUND_COLOUR);
        }
        Vec P = O.add(D.scale(closestDistance));
        Vec N = P.subtract(Vec.of(SphereGeometry.centre(closest))).normalised();
        return illuminate(scene, closest, P, N);
    }

    /**
     * The exact distance s &gt; 0 to the nearest intersection, or null for none: the smaller root
     * of a s^2 + 2 beta s + c = 0 (a = D.D, beta = D.(O - C), c = |O - C|^2 - r^2) that is
     * positive, exactly as the spec defines it.
     *
     * <p>The roots are taken as q / a and c / q with q = -(beta + sign(beta) sqrt(Delta)) rather
     * than (-beta -+ sqrt(Delta)) / a. Even in 106 bits the textbook form turns a root that is
     * exactly 0 (a ray starting on the surface, c = 0) into +-1e-32, and its sign would decide
     * whether the ray hits the surface it starts on; c / q is exactly 0 there.
     */
    public static DoubleDouble hitDistance(Sphere sphere, Ray ray) {
        return hitDistance(sphere, ray,
                exactC(ray.getOrigin(), SphereGeometry.centre(sphere), SphereGeometry.radius(sphere)));
    }

    private static DoubleDouble hitDistance(Sphere sphere, Ray ray, DoubleDouble c) {
        Vec D = Vec.of(ray.getDirection());
        Vec f = Vec.of(ray.getOrigin()).subtract(Vec.of(SphereGeometry.centre(sphere)));
        DoubleDouble a = D.dot(D);
        DoubleDouble beta = D.dot(f);
        DoubleDouble quarterDiscriminant = beta.multiply(beta).subtract(a.multiply(c));
        if (quarterDiscriminant.signum() < 0) {
            return null;
        }
        DoubleDouble root = quarterDiscriminant.sqrt();
        DoubleDouble q = (beta.signum() < 0 ? beta.subtract(root) : beta.add(root)).negate();
        if (q.signum() == 0) {
            return null; // beta = Delta = c = 0: both roots are 0
        }
        DoubleDouble t0 = c.divide(q), t1 = q.divide(a);
        DoubleDouble near = t0.min(t1), far = t0.max(t1);
        DoubleDouble s = near.signum() > 0 ? near : far;
        return s.signum() > 0 ? s : null;
    }

    /**
     * c = |O - C|^2 - r^2 exactly (then rounded to 106 bits). Under a giant floor sphere |O - C|^2
     * and r^2 agree in 30 of their 32 digits, more than a double-double can hold, so this one
     * quantity is computed in BigDecimal, whose sums and products of doubles are exact.
     */
    private static DoubleDouble exactC(Vector3 O, Vector3 C, double r) {
        BigDecimal fx = new BigDecimal(O.x).subtract(new BigDecimal(C.x));
        BigDecimal fy = new BigDecimal(O.y).subtract(new BigDecimal(C.y));
        BigDecimal fz = new BigDecimal(O.z).subtract(new BigDecimal(C.z));
        BigDecimal rr = new BigDecimal(r);
        BigDecimal c = fx.multiply(fx).add(fy.multiply(fy)).add(fz.multiply(fz)).subtract(rr.multiply(rr));
        double hi = c.doubleValue();
        return DoubleDouble.twoSum(hi, c.subtract(new BigDecimal(hi)).doubleValue());
    }

    /** The spec's Phong model, term for term as {@link Renderer} computes it. */
    private static Vec illuminate(Scene scene, Sphere object, Vec P, Vec N) {
        Vec C_diff = Vec.of(object.getColour());
        Vec ambient = C_diff.scale(Vec.of(scene.getAmbientLighting()));
        PointLight light = scene.getPointLight();
        if (light == null) {
            return ambient;
        }
        Vec toLight = Vec.of(light.getPosition()).subtract(P);
        DoubleDouble d = toLight.magnitude();
        DoubleDouble fourPiDSquared = DoubleDouble.PI.multiply(4).multiply(d).multiply(d);
        Vec I = Vec.of(light.getColour()).scale(DoubleDouble.of(light.getIntensity()).divide(fourPiDSquared));

        DoubleDouble k_d = DoubleDouble.of(object.getPhong_kD());
        DoubleDouble k_s = DoubleDouble.of(object.getPhong_kS());
        Vec L = toLight.normalised();
        Vec V = P.negate().normalised();
        Vec R = N.scale(TWO.multiply(L.dot(N))).subtract(L);

        DoubleDouble NdotL = N.dot(L).max(DoubleDouble.ZERO);
        DoubleDouble RdotV = R.dot(V).max(DoubleDouble.ZERO);
        DoubleDouble specularPower = power(RdotV, (int) object.getPhong_n());

        Vec diffuse = C_diff.scale(I).scale(k_d.multiply(NdotL));
        Vec specular = I.scale(k_s.multiply(specularPower)); // C_spec = (1, 1, 1)
        return ambient.add(diffuse).add(specular);
    }

    private static DoubleDouble power(DoubleDouble base, int n) {
        DoubleDouble result = DoubleDouble.ONE;
        for (int i = 0; i < n; i++) {
            result = result.multiply(base);
        }
        return result;
    }

    /** The spec's pixel value of an exact colour: clamp to [0, 1], times 255, truncate. */
    public static int toRGB(Vec colour) {
        return toByte(colour.x) << 16 | toByte(colour.y) << 8 | toByte(colour.z);
    }

    private static int toByte(DoubleDouble channel) {
        DoubleDouble clamped = channel.max(DoubleDouble.ZERO).min(DoubleDouble.ONE);
        return (int) clamped.multiply(255).floor();
    }

    /** A 3-vector of double-doubles: just the operations the spec's formulas use. */
    public static final class Vec {
        public final DoubleDouble x, y, z;

        Vec(DoubleDouble x, DoubleDouble y, DoubleDouble z) {
            this.x = x;
            this.y = y;
            this.z = z;
        }

        static Vec of(Vector3 v) {
            return new Vec(DoubleDouble.of(v.x), DoubleDouble.of(v.y), DoubleDouble.of(v.z));
        }

        Vec add(Vec o) {
            return new Vec(x.add(o.x), y.add(o.y), z.add(o.z));
        }

        Vec subtract(Vec o) {
            return new Vec(x.subtract(o.x), y.subtract(o.y), z.subtract(o.z));
        }

        Vec negate() {
            return new Vec(x.negate(), y.negate(), z.negate());
        }

        Vec scale(DoubleDouble k) {
            return new Vec(x.multiply(k), y.multiply(k), z.multiply(k));
        }

        Vec scale(Vec o) {
            return new Vec(x.multiply(o.x), y.multiply(o.y), z.multiply(o.z));
        }

        DoubleDouble dot(Vec o) {
            return x.multiply(o.x).add(y.multiply(o.y)).add(z.multiply(o.z));
        }

        DoubleDouble magnitude() {
            return dot(this).sqrt();
        }

        Vec normalised() {
            DoubleDouble m = magnitude();
            return new Vec(x.divide(m), y.divide(m), z.divide(m));
        }
    }
}
