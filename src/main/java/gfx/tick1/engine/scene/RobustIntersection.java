package gfx.tick1.engine.scene;

import gfx.tick1.engine.math.DoubleDouble;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;

/**
 * The renderer's default ray-sphere intersection: the handout's result wherever a rounding-error
 * bound proves it accurate, and a numerically stable computation of the same root everywhere else.
 *
 * <h2>Why not always the stable formula?</h2>
 * The course's images are made with the handout's formula in doubles. Any other formula rounds s
 * differently, moves P by an ulp, and now and then tips a channel across a truncation boundary:
 * on ordinary scenes the reference build must not do that. So the handout's s is kept whenever
 * its error is provably small, which on ordinary scenes is every time (the tests check this on
 * every scene in {@code scenes/} and on hundreds of generated ones).
 *
 * <h2>The maths</h2>
 * With f = O - C, the ray O + sD meets |P - C| = r where a s^2 + 2 beta s + c = 0, with
 * a = D.D, beta = D.f, c = f.f - r^2. Its quarter discriminant is
 * <pre>
 *     Delta = beta^2 - a c  =  a r^2 - |D x f|^2      (Lagrange: |D|^2 |f|^2 - (D.f)^2 = |D x f|^2)
 * </pre>
 * and its roots are (-beta -+ sqrt(Delta)) / a. The handout computes b^2 - 4ac with b = 2 beta.
 *
 * <p><b>Where the handout's formula loses accuracy.</b> With u = 2^-53 the unit roundoff, the
 * handout's b^2 - 4ac carries an absolute error of a few u times b^2 + 4a(f.f + r^2), however small
 * the discriminant itself is. Two things make that error large compared with what it measures:
 * <ul>
 * <li>a sphere small for its distance (|f| &gt;&gt; r): Delta ~ a (r^2 - d_perp^2) is tiny against
 *   a |f|^2, and the hit-or-miss decision is noise once r^2 / |f|^2 nears u;</li>
 * <li>a ray origin near the surface (|f| ~ r, as under a giant floor sphere): c = f.f - r^2
 *   cancels, and the near root (-b - sqrt(disc)) / 2a cancels again, so s loses about
 *   log2(r / (|f| - r)) bits.</li>
 * </ul>
 *
 * <p><b>The stable computation</b> (Ray Tracing Gems ch. 7, Haines et al. 2019; pbrt-v4's
 * sphere) removes both:
 * <ul>
 * <li>a, beta and c with error-free transformations: every product D_i D_i, f_i D_i, f_i f_i, r r
 *   is split exactly by fma into a double and its rounding error, and the sums are taken in
 *   double-double, so c keeps its relative accuracy even when f.f and r^2 agree in 40 of their
 *   53 bits (the giant floor).</li>
 * <li>Delta either as beta^2 - a c in double-double from those, or in the geometric form
 *   a r^2 - |D x f|^2 with each component of D x f computed by Kahan's fma difference of
 *   products: whichever has the smaller error bound (see {@link #quarterDiscriminant}). The
 *   geometric form's error is a few u times a r^2 however far away the sphere is, which is as
 *   good as the inputs allow (one ulp more radius changes Delta by 2u a r^2); it is needed only
 *   for spheres more than about 1e7 radii away.</li>
 * <li>q = -(beta + sign(beta) sqrt(Delta)) adds two numbers of the same sign, so it does not
 *   cancel; the roots are c / q and q / a (their product is c / a, as Vieta requires). Both are
 *   accurate to a few ulps.</li>
 * </ul>
 *
 * <p><b>The switch.</b> Let E = 16u (beta_abs^2 + a (f.f + r^2)), with beta_abs = sum |D_i f_i|.
 * A standard forward error analysis (Higham, <i>Accuracy and Stability of Numerical Algorithms</i>,
 * ch. 3: a dot product of n terms is off by at most gamma_n = n u / (1 - n u) times the sum of the
 * terms' magnitudes) bounds the handout's b^2 - 4ac, divided by 4, within E of the exact Delta; the
 * factor 16 covers the ten or so roundings with room to spare. Then:
 * <ul>
 * <li>if Delta &lt; -2E, both the handout and the exact answer miss;</li>
 * <li>if Delta &gt; 2E, the handout's discriminant is positive and each of its roots is within
 *   E_s = (E / sqrt(Delta) + 4u (beta_abs + sqrt(Delta))) / a + 16u |s| of the exact root (the
 *   first term is sqrt's sensitivity to the discriminant's error, the second the rounding of
 *   -b -+ sqrt, the third of the division and of a). When both roots are farther than E_s from
 *   0, the handout picks the same root as exact arithmetic would; when also E_s &lt;=
 *   {@link #TOLERANCE} s, its s is used as it is.</li>
 * <li>otherwise the handout's answer may be wrong, or right only by luck, and the stable
 *   computation decides.</li>
 * </ul>
 * Delta and the roots that the test compares with E and E_s are the stable ones, accurate to a
 * few u relative to a r^2 and s, well inside the margins.
 */
public final class RobustIntersection {

    private static final double U = 0x1p-53;
    private static final double DISCRIMINANT_BOUND = 16 * U;

    /**
     * The largest relative error in s for which the handout's result is kept: 2^-30, about 1e-9.
     * An error that small moves P by a billionth of its distance, which changes a shaded channel
     * by far less than one level unless the light nearly touches the surface. The handout's error
     * on the tick's scenes is around 1e-15, so nothing ordinary comes near it; the giant floor
     * spheres and far small spheres of {@code scenes/hard} go past it.
     */
    public static final double TOLERANCE = 0x1p-30;

    private RobustIntersection() {
    }

    /** The default: the handout's hit where it is provably accurate, the stable one elsewhere. */
    public static RaycastHit intersect(Sphere sphere, Ray ray) {
        return intersect(sphere, ray, true);
    }

    /**
     * The stable computation alone, never the handout's. It is at least as accurate, but it rounds
     * differently and so is not bit-identical to the course's images (see docs/hard-cases.md);
     * kept for measurements.
     */
    public static RaycastHit stable(Sphere sphere, Ray ray) {
        return intersect(sphere, ray, false);
    }

    private static RaycastHit intersect(Sphere sphere, Ray ray, boolean keepHandoutWhereAccurate) {
        Vector3 O = ray.getOrigin();
        Vector3 D = ray.getDirection();
        Vector3 C = SphereGeometry.centre(sphere);
        // f = O - C is exact for the camera's rays (O = 0). For other origins its rounding is a
        // relative change of u in f: the answer for a sphere moved by u |O - C| at most.
        double s = nearestRoot(D.x, D.y, D.z, O.x - C.x, O.y - C.y, O.z - C.z, SphereGeometry.radius(sphere),
                keepHandoutWhereAccurate);
        if (s == HANDOUT_IS_ACCURATE) {
            return sphere.intersectionWith(ray);
        }
        if (!(s > 0)) {
            return new RaycastHit();
        }
        Vector3 point = ray.evaluateAt(s);
        return new RaycastHit(sphere, s, point, sphere.getNormalAt(point));
    }

    /**
     * What {@link #nearestRoot} answers when the handout's own result is provably accurate and
     * should be used as it is. It is -1, which no answer of a root could be (those are &gt; 0 or
     * not a hit), so callers can test it with ==.
     */
    public static final double HANDOUT_IS_ACCURATE = -1;

    /**
     * The robust decision for the ray with direction D from a point f = O - C relative to the
     * centre of a sphere of radius r: {@link #HANDOUT_IS_ACCURATE} when
     * {@code keepHandoutWhereAccurate} and the handout's formula is provably accurate here; else
     * the stable nearest root, which is not &gt; 0 when the ray misses. Shared by
     * {@link Sphere}-level callers and the fast renderer, so the two decide alike by construction.
     */
    public static double nearestRoot(double dx, double dy, double dz, double fx, double fy, double fz, double r,
            boolean keepHandoutWhereAccurate) {
        return nearestRoot(dx, dy, dz, dx * dx + dy * dy + dz * dz, Offset.of(fx, fy, fz, r), keepHandoutWhereAccurate);
    }

    /**
     * The terms of the quadratic that depend on the sphere and the ray's origin but not on its
     * direction: f = O - C, f.f, r^2 and c = f.f - r^2 in double-double. Every camera ray starts
     * at the origin, so a renderer can compute them once per sphere instead of once per ray.
     */
    public record Offset(double fx, double fy, double fz, double ff, double rr, DoubleDouble exactC) {

        public static Offset of(double fx, double fy, double fz, double r) {
            return new Offset(fx, fy, fz, fx * fx + fy * fy + fz * fz, r * r,
                    exactDot(fx, fy, fz, fx, fy, fz).subtract(DoubleDouble.twoProduct(r, r)));
        }
    }

    /**
     * {@link #nearestRoot(double, double, double, double, double, double, double, boolean)} with
     * a = D.D and the sphere's {@link Offset} computed beforehand.
     */
    public static double nearestRoot(double dx, double dy, double dz, double a, Offset offset,
            boolean keepHandoutWhereAccurate) {
        return nearestRoot(dx, dy, dz, a, offset, keepHandoutWhereAccurate, true);
    }

    /** As above; {@code quickAccept} false skips {@link #handoutCertainlyAccurate}, for its test. */
    static double nearestRoot(double dx, double dy, double dz, double a, Offset offset,
            boolean keepHandoutWhereAccurate, boolean quickAccept) {
        double roughBeta = roughBeta(dx, dy, dz, offset);
        double betaAbs = betaAbs(dx, dy, dz, offset);
        double E = discriminantBound(a, betaAbs, offset);
        double roughDelta = roughDelta(a, roughBeta, offset);
        // Most rays miss most spheres by far: decided here, before the quick test's square root.
        if (certainlyMisses(roughDelta, E)) {
            return Double.NEGATIVE_INFINITY;
        }
        if (keepHandoutWhereAccurate && quickAccept && quickAccepts(a, roughBeta, betaAbs, roughDelta, E)) {
            return HANDOUT_IS_ACCURATE;
        }
        return carefulNearestRoot(dx, dy, dz, a, offset, betaAbs, E, keepHandoutWhereAccurate);
    }

    /**
     * The quick test, {@link #handoutCertainlyAccurate}, with its arithmetic done by the helpers
     * below.
     */
    static boolean quickAccepts(double a, double roughBeta, double betaAbs, double roughDelta, double E) {
        double sqrtLow = quickSquareRoot(roughDelta, E);
        double overA = 1 / a, sensitivity = E * (1 / sqrtLow);
        double near = quickNear(roughBeta, sqrtLow, overA), far = quickFar(roughBeta, sqrtLow, overA);
        double spread = quickSpread(betaAbs, sensitivity, overA, near, far);
        double rootError = quickRootError(betaAbs, sensitivity, sqrtLow, overA, quickLargest(near, far, spread));
        return handoutCertainlyAccurate(roughDelta, E, near, far, spread, rootError);
    }

    /** beta = D.f in plain doubles, as the handout computes it (its b is 2 beta, exactly). */
    public static double roughBeta(double dx, double dy, double dz, Offset offset) {
        return dx * offset.fx() + dy * offset.fy() + dz * offset.fz();
    }

    /** sum |D_i f_i|: the size of the terms of beta, which its rounding error is relative to. */
    static double betaAbs(double dx, double dy, double dz, Offset offset) {
        return Math.abs(dx * offset.fx()) + Math.abs(dy * offset.fy()) + Math.abs(dz * offset.fz());
    }

    /** E: the bound on the error of the handout's discriminant, divided by 4 (see the class comment). */
    static double discriminantBound(double a, double betaAbs, Offset offset) {
        return DISCRIMINANT_BOUND * (betaAbs * betaAbs + a * (offset.ff() + offset.rr()));
    }

    /** Delta = beta^2 - a c in plain doubles: within E of the exact value. */
    static double roughDelta(double a, double roughBeta, Offset offset) {
        return roughBeta * roughBeta - a * (offset.ff() - offset.rr());
    }

    /** Below -2E both the handout and exact arithmetic certainly miss. */
    private static boolean certainlyMisses(double roughDelta, double E) {
        return roughDelta < -2 * E;
    }

    /**
     * sqrt(roughDelta - 2E), a lower bound on sqrt(Delta): the quick test's one square root. NaN
     * when the argument is negative, which the quick test rejects.
     */
    private static double quickSquareRoot(double roughDelta, double E) {
        return Math.sqrt(roughDelta - 2 * E);
    }

    /**
     * The decision in double-double, past the quick tests. In a method of its own so that the
     * quick part above, which decides almost every ray, stays small enough for the JIT to inline
     * into a renderer's loop.
     */
    private static double carefulNearestRoot(double dx, double dy, double dz, double a, Offset offset, double betaAbs,
            double E, boolean keepHandoutWhereAccurate) {
        double fx = offset.fx(), fy = offset.fy(), fz = offset.fz();
        double ff = offset.ff(), rr = offset.rr();
        DoubleDouble exactA = exactDot(dx, dy, dz, dx, dy, dz);
        DoubleDouble exactBeta = exactDot(dx, dy, dz, fx, fy, fz);
        DoubleDouble exactC = offset.exactC();
        double delta = quarterDiscriminant(exactA, exactBeta, exactC, a, dx, dy, dz, fx, fy, fz, rr, ff);
        if (delta < -2 * E) {
            return Double.NEGATIVE_INFINITY;
        }
        double beta = exactBeta.doubleValue();
        double c = exactC.doubleValue();

        Roots roots = Roots.of(a, beta, c, delta);
        if (keepHandoutWhereAccurate && delta > 2 * E && handoutIsAccurate(roots, a, betaAbs, delta, E)) {
            return HANDOUT_IS_ACCURATE;
        }
        double s = roots.nearestPositive();
        return s > 0 ? s : Double.NEGATIVE_INFINITY;
    }

    /**
     * A quick sufficient condition for the decision below to keep the handout's result, from the
     * double estimates roughBeta and roughDelta alone: when it holds, the double-double work
     * would reach the same answer, so it is skipped. This is what makes the robust method nearly
     * as fast as the handout's on ordinary scenes, where it holds for almost every hit.
     *
     * <p>Why it implies the slow test. roughDelta is within E of the exact Delta (the estimate
     * in {@link #nearestRoot}), so roughDelta &gt; 4E gives Delta &gt; 2E with room to spare.
     * The roots (-roughBeta -+ sqrtLow) / a, with sqrtLow = sqrt(roughDelta - 2E), are within
     * {@code spread} of the exact ones (and so of the stable ones the slow test computes):
     * roughBeta is off by at most 4u betaAbs, sqrtLow from sqrt(Delta) by at most 2E / sqrtLow,
     * and the roundings of the two computations add 8u of each root. {@code rootError} is the slow test's bound with
     * every input replaced by the side that makes it larger (sqrt(Delta) by sqrtLow below a
     * division, by sqrtHigh elsewhere, the largest root by ours plus the spread), so it bounds
     * the slow test's value. Asking for twice that bound, beyond the spread, leaves the slow
     * test's own roundings (a few ulps) no way to come out differently: both roots are clear of
     * 0 by more than its bound, keep their signs, and the nearest positive one passes its
     * TOLERANCE test. RobustIntersectionShortcutTest checks on hard and ordinary inputs that the
     * answers with and without this shortcut are the same.
     *
     * <p>Its arithmetic is in the helpers below ({@link #quickSquareRoot}, {@link #quickNear},
     * {@link #quickFar}, {@link #quickSpread}, {@link #quickRootError}), one named step of the
     * bound each; only the comparisons are here. Multiplying by the reciprocals
     * 1 / a and 1 / sqrtLow instead of dividing rounds differently by an ulp, which the factors
     * of 2 and 8u absorb.
     */
    static boolean handoutCertainlyAccurate(double roughDelta, double E, double near, double far, double spread,
            double rootError) {
        if (!(roughDelta > 4 * E)) {
            return false;
        }
        double clearance = 2 * rootError + spread;
        if (!(Math.abs(near) > clearance && Math.abs(far) > clearance)) {
            return false;
        }
        double s = near > 0 ? near : far;
        return s > 0 && 2 * rootError <= TOLERANCE * (s - spread);
    }

    /** The quick test's near root (-roughBeta - sqrtLow) / a. */
    private static double quickNear(double roughBeta, double sqrtLow, double overA) {
        return (-roughBeta - sqrtLow) * overA;
    }

    /** The quick test's far root (-roughBeta + sqrtLow) / a. */
    private static double quickFar(double roughBeta, double sqrtLow, double overA) {
        return (-roughBeta + sqrtLow) * overA;
    }

    /**
     * How far the quick roots may be from the exact ones. {@code sensitivity} is E / sqrtLow,
     * which bounds sqrt(Delta) - sqrtLow by twice itself (sqrt(x + 3E) &lt;= sqrt(x) + 3E / (2 sqrt(x))).
     */
    private static double quickSpread(double betaAbs, double sensitivity, double overA, double near, double far) {
        return (4 * U * betaAbs + 2 * sensitivity) * overA + 8 * U * (Math.abs(near) + Math.abs(far));
    }

    /** An upper bound on the larger of the exact roots' magnitudes. */
    private static double quickLargest(double near, double far, double spread) {
        return Math.max(Math.abs(near), Math.abs(far)) + spread;
    }

    /**
     * The careful test's bound on the roots' error, with every input on the side that makes it
     * larger: sqrt(Delta) by sqrtLow below a division, by sqrtLow + 2 sensitivity elsewhere, and
     * the largest root by {@link #quickLargest}.
     */
    private static double quickRootError(double betaAbs, double sensitivity, double sqrtLow, double overA,
            double largest) {
        double sqrtHigh = sqrtLow + 2 * sensitivity;
        return (sensitivity + 4 * U * (betaAbs + sqrtHigh)) * overA + 16 * U * largest;
    }

    /** Whether the handout's roots have the exact roots' signs and its chosen s is within TOLERANCE. */
    private static boolean handoutIsAccurate(Roots roots, double a, double betaAbs, double delta, double E) {
        double sqrtDelta = Math.sqrt(delta);
        double largest = Math.max(Math.abs(roots.near), Math.abs(roots.far));
        double rootError = (E / sqrtDelta + 4 * U * (betaAbs + sqrtDelta)) / a + 16 * U * largest;
        if (Math.abs(roots.near) <= rootError || Math.abs(roots.far) <= rootError) {
            return false;
        }
        double s = roots.nearestPositive();
        return !(s > 0) || rootError <= TOLERANCE * s;
    }

    /**
     * Delta = beta^2 - a c = a r^2 - |D x f|^2, by whichever of two evaluations has the smaller
     * error bound here.
     * <ul>
     * <li>Algebraic, in double-double from the near-exact a, beta and c: off by at most about
     *   2^-100 a (2 f.f + r^2). Under a giant floor, where Delta ~ beta^2 is large and c small,
     *   that is far better than a double.</li>
     * <li>Geometric, a r^2 - |D x f|^2: each component of D x f is Kahan's difference of products,
     *   within 1.5 ulp of its exact value, so Delta is off by at most about 16u a r^2, however far
     *   away the sphere is. It wins when r^2 &lt; 2^-48 f.f: spheres more than ten million radii away.</li>
     * </ul>
     */
    private static double quarterDiscriminant(DoubleDouble exactA, DoubleDouble beta, DoubleDouble c, double a,
            double dx, double dy, double dz, double fx, double fy, double fz, double rr, double ff) {
        if (16 * U * rr < 0x1p-100 * (2 * ff + rr)) {
            return a * rr - squaredMagnitudeOfCross(dx, dy, dz, fx, fy, fz);
        }
        return beta.multiply(beta).subtract(exactA.multiply(c)).doubleValue();
    }

    /**
     * |D x f|^2. Each component y1 z2 - z1 y2 is Kahan's difference of products: fma gives the
     * rounding error of one product exactly, so the result is within 1.5 ulp of the exact one
     * even when the two products nearly cancel (a ray almost through the centre).
     */
    static double squaredMagnitudeOfCross(double dx, double dy, double dz, double fx, double fy, double fz) {
        double wx = differenceOfProducts(dy, fz, dz, fy);
        double wy = differenceOfProducts(dz, fx, dx, fz);
        double wz = differenceOfProducts(dx, fy, dy, fx);
        return wx * wx + wy * wy + wz * wz;
    }

    /** a b - c d to within 1.5 ulp (Kahan; Jeannerod, Louvet and Muller 2013). */
    static double differenceOfProducts(double a, double b, double c, double d) {
        double cd = c * d;
        double error = Math.fma(-c, d, cd);
        double difference = Math.fma(a, b, -cd);
        return difference + error;
    }

    /** x1 y1 + x2 y2 + x3 y3 with every product split exactly by fma and summed in double-double. */
    static DoubleDouble exactDot(double x1, double x2, double x3, double y1, double y2, double y3) {
        return DoubleDouble.twoProduct(x1, y1).add(DoubleDouble.twoProduct(x2, y2))
                .add(DoubleDouble.twoProduct(x3, y3));
    }

    /** The two roots of a s^2 + 2 beta s + c = 0, near &lt;= far, from the stable q form. */
    private static final class Roots {
        final double near, far;

        private Roots(double near, double far) {
            this.near = near;
            this.far = far;
        }

        static Roots of(double a, double beta, double c, double delta) {
            if (delta < 0) {
                return new Roots(Double.NaN, Double.NaN);
            }
            // -beta and -sign(beta) sqrt(Delta) have the same sign: q never cancels.
            double q = -(beta + Math.copySign(Math.sqrt(delta), beta));
            if (q == 0) {
                // beta = 0 and Delta = 0, so c = 0: a ray along the tangent plane from a point on
                // the sphere. Both roots are 0, and s = 0 is not a hit.
                return new Roots(0, 0);
            }
            double t0 = c / q, t1 = q / a;
            return new Roots(Math.min(t0, t1), Math.max(t0, t1));
        }

        /** The nearest root with s &gt; 0, or a value that is not &gt; 0 when there is none. */
        double nearestPositive() {
            return near > 0 ? near : far;
        }
    }
}
