package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.math.Vector3;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The error bounds that {@link RobustIntersection} rests on, checked directly against exact
 * arithmetic (as pbrt tests its bounds), not only through the images they lead to. The inputs are
 * doubles, so BigDecimal holds them, and their exact products and sums, without rounding.
 *
 * <p>For a camera ray (O = 0) the offset f = O - C = -C is exact. With Delta = beta^2 - a c the
 * exact quarter discriminant, the class comment claims: the plain-double estimate roughDelta and
 * the handout's (b^2 - 4ac) / 4 are both within E of Delta; and where Delta &gt; 2E the handout's
 * discriminant is positive and each of its roots is within E_s = (E / sqrt(Delta) + 4u (beta_abs +
 * sqrt(Delta))) / a + 16u |s| of the exact root s.
 */
class RobustIntersectionBoundsTest {

    private static final double U = 0x1p-53;
    private static final MathContext PRECISE = new MathContext(60);
    private static final int CASES = 4000;

    /** Families of inputs, from the tick's ordinary scenes to the hard ones of scenes/hard. */
    enum Family {
        ORDINARY, GIANT_FLOOR, FAR_SMALL_SPHERE, GRAZING
    }

    /** A camera ray's direction D and a sphere at C of radius r. */
    private record Case(Vector3 D, Vector3 C, double r) {
    }

    private static List<Case> cases(Family family) {
        SplittableRandom random = new SplittableRandom(family.ordinal() * 7919L + 1);
        List<Case> cases = new ArrayList<>();
        for (int i = 0; i < CASES; i++) {
            // The camera's directions: x and y within the frame's half-width, z = 1, normalised or not.
            Vector3 D = new Vector3(random.nextDouble(-0.42, 0.42), random.nextDouble(-0.32, 0.32), 1);
            if (random.nextBoolean()) {
                D = D.normalised();
            }
            switch (family) {
                case ORDINARY -> cases.add(new Case(D, new Vector3(random.nextDouble(-3, 3), random.nextDouble(-3, 3),
                        random.nextDouble(1, 30)), random.nextDouble(0.05, 3)));
                case GIANT_FLOOR -> {
                    double r = Math.pow(10, random.nextDouble(3, 16));
                    cases.add(new Case(D, new Vector3(random.nextDouble(-5, 5), -(r + random.nextDouble(0.2, 3)),
                            random.nextDouble(0, 20)), r));
                }
                case FAR_SMALL_SPHERE -> {
                    double distance = Math.pow(10, random.nextDouble(2, 15));
                    Vector3 C = D.normalised().scale(distance).add(new Vector3(random.nextDouble(-1, 1),
                            random.nextDouble(-1, 1), 0).scale(distance * 1e-3));
                    cases.add(new Case(D, C, distance * Math.pow(10, -random.nextDouble(1, 9))));
                }
                case GRAZING -> {
                    // A sphere placed so that the ray passes at a distance r (1 +- 1e-k) from C.
                    Vector3 unit = D.normalised();
                    Vector3 side = unit.cross(new Vector3(0, 1, 0)).normalised();
                    double r = random.nextDouble(0.1, 5);
                    double miss = r * (1 + (random.nextBoolean() ? 1 : -1) * Math.pow(10, -random.nextDouble(1, 15)));
                    cases.add(new Case(D, unit.scale(random.nextDouble(5, 50)).add(side.scale(miss)), r));
                }
                default -> throw new IllegalStateException();
            }
        }
        return cases;
    }

    private static BigDecimal exact(double x) {
        return new BigDecimal(x);
    }

    private static BigDecimal dot(Vector3 a, Vector3 b) {
        return exact(a.x).multiply(exact(b.x)).add(exact(a.y).multiply(exact(b.y)))
                .add(exact(a.z).multiply(exact(b.z)));
    }

    /** What the bounds are about, for one case: the exact and the computed quantities side by side. */
    private record Quantities(double a, double E, double betaAbs, double roughDelta, double handoutDiscriminant,
            BigDecimal exactBeta, BigDecimal exactA, BigDecimal exactDelta) {

        static Quantities of(Case input) {
            Vector3 f = new Vector3(0).subtract(input.C());
            RobustIntersection.Offset offset = RobustIntersection.Offset.of(f.x, f.y, f.z, input.r());
            Vector3 D = input.D();
            double a = D.dot(D);
            double betaAbs = RobustIntersection.betaAbs(D.x, D.y, D.z, offset);
            double roughBeta = RobustIntersection.roughBeta(D.x, D.y, D.z, offset);
            // The handout's own arithmetic (Sphere.intersectionWith): b = 2 D.f, c = f.f - r^2.
            double b = 2 * D.dot(f);
            double c = f.dot(f) - Math.pow(input.r(), 2);
            BigDecimal exactBeta = dot(D, f);
            BigDecimal exactA = dot(D, D);
            BigDecimal exactC = dot(f, f).subtract(exact(input.r()).multiply(exact(input.r())));
            return new Quantities(a, RobustIntersection.discriminantBound(a, betaAbs, offset), betaAbs,
                    RobustIntersection.roughDelta(a, roughBeta, offset), b * b - 4 * a * c, exactBeta, exactA,
                    exactBeta.multiply(exactBeta).subtract(exactA.multiply(exactC)));
        }

        double errorOf(double estimate) {
            return exact(estimate).subtract(exactDelta).abs().doubleValue();
        }
    }

    @ParameterizedTest
    @EnumSource(Family.class)
    void theRoughDiscriminantIsWithinEOfTheExactOne(Family family) {
        for (Case input : cases(family)) {
            Quantities q = Quantities.of(input);
            assertThat(q.errorOf(q.roughDelta())).as("|roughDelta - Delta| for %s, E = %s", input, q.E())
                    .isLessThanOrEqualTo(q.E());
        }
    }

    @ParameterizedTest
    @EnumSource(Family.class)
    void theHandoutsDiscriminantIsWithinEOfTheExactOne(Family family) {
        for (Case input : cases(family)) {
            Quantities q = Quantities.of(input);
            assertThat(q.errorOf(q.handoutDiscriminant() / 4))
                    .as("|(b^2 - 4ac) / 4 - Delta| for %s, E = %s", input, q.E())
                    .isLessThanOrEqualTo(q.E());
        }
    }

    @ParameterizedTest
    @EnumSource(Family.class)
    void whereTheDiscriminantIsClearOfItsErrorTheHandoutsRootsAreWithinTheirBound(Family family) {
        int checked = 0;
        for (Case input : cases(family)) {
            Quantities q = Quantities.of(input);
            if (q.exactDelta().compareTo(exact(2 * q.E())) <= 0) {
                continue;
            }
            checked++;
            assertThat(q.handoutDiscriminant()).as("the handout's discriminant for %s", input).isPositive();
            double root = Math.sqrt(q.handoutDiscriminant());
            BigDecimal sqrtDelta = q.exactDelta().sqrt(PRECISE);
            // The handout's roots, as Sphere.intersectionWith computes them.
            double b = 2 * input.D().dot(new Vector3(0).subtract(input.C()));
            double[] handout = {(-b - root) / (2 * q.a()), (-b + root) / (2 * q.a())};
            BigDecimal[] exactRoots = {
                q.exactBeta().negate().subtract(sqrtDelta).divide(q.exactA(), PRECISE),
                q.exactBeta().negate().add(sqrtDelta).divide(q.exactA(), PRECISE)};
            for (int i = 0; i < 2; i++) {
                double s = exactRoots[i].doubleValue();
                double sqrtD = sqrtDelta.doubleValue();
                double bound = (q.E() / sqrtD + 4 * U * (q.betaAbs() + sqrtD)) / q.a() + 16 * U * Math.abs(s);
                assertThat(exact(handout[i]).subtract(exactRoots[i]).abs().doubleValue())
                        .as("the error of the handout's %s root for %s (exact %s, bound E_s = %s)",
                                i == 0 ? "near" : "far", input, s, bound)
                        .isLessThanOrEqualTo(bound);
            }
        }
        assertThat(checked).as("cases with Delta > 2E among %d of %s", CASES, family).isGreaterThan(CASES / 20);
    }
}
