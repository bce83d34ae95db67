package gfx.tick1.engine.render;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.math.DoubleDouble;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The truth renderer against answers known in closed form, and against BigDecimal arithmetic. */
class TruthRendererTest {

    private static final Vector3 ORIGIN = new Vector3(0);
    private static final Vector3 GREY = new Vector3(0.5);

    private static DoubleDouble s(Vector3 centre, double radius, Vector3 direction) {
        return TruthRenderer.hitDistance(new Sphere(centre, radius, GREY), new Ray(ORIGIN, direction));
    }

    private static BigDecimal exact(DoubleDouble value) {
        return new BigDecimal(value.hi).add(new BigDecimal(value.lo));
    }

    @Test
    void alongTheAxisTheHitIsTheCentresDistanceLessTheRadius() {
        assertThat(exact(s(new Vector3(0, 0, 5), 1, new Vector3(0, 0, 1)))).isEqualByComparingTo("4");
        // A sphere of radius 1e16 - 8 whose near side is 8 units away: f.f - r^2 cancels in 16 digits.
        assertThat(exact(s(new Vector3(0, 0, 1e16), 1e16 - 8, new Vector3(0, 0, 1)))).isEqualByComparingTo("8");
    }

    @Test
    void straightDownAGiantFloorSphereIsHit2UnitsBelow() {
        assertThat(exact(s(new Vector3(0, -1e16, 0), 1e16 - 2, new Vector3(0, -1, 0)))).isEqualByComparingTo("2");
        assertThat(exact(s(new Vector3(0, -3000000000000002.0, 0), 3e15, new Vector3(0, -1, 0))))
                .isEqualByComparingTo("2");
    }

    @Test
    void aTangentRayTouchesAtOnePoint() {
        DoubleDouble s = TruthRenderer.hitDistance(new Sphere(new Vector3(0, 0, 5), 1, GREY),
                new Ray(new Vector3(1, 0, 0), new Vector3(0, 0, 1)));
        assertThat(exact(s)).isEqualByComparingTo("5");
    }

    @Test
    void fromTheSurfaceTheRayHitsTheFarSideAndNeverAtZero() {
        // Sphere through the origin: the roots are 0 and -2 beta / a = 6 D.z for a unit D.
        Vector3 D = new Vector3(0.1, 0.2, 1).normalised();
        DoubleDouble s = s(new Vector3(0, 0, 3), 3, D);
        BigDecimal a = new BigDecimal(D.x).pow(2).add(new BigDecimal(D.y).pow(2)).add(new BigDecimal(D.z).pow(2));
        BigDecimal expected = new BigDecimal(6).multiply(new BigDecimal(D.z)).divide(a, MathContext.DECIMAL128);
        assertThat(exact(s).subtract(expected).abs()).isLessThan(new BigDecimal("1e-30"));
        assertThat(s(new Vector3(0, 0, 3), 3, new Vector3(0, 0, -1))).as("looking away from it").isNull();
    }

    @Test
    void fromTheCentreEveryRayHitsAtTheRadius() {
        Vector3 D = new Vector3(0.3, -0.7, 0.2).normalised();
        BigDecimal length = exact(DoubleDouble.twoProduct(D.x, D.x).add(DoubleDouble.twoProduct(D.y, D.y))
                .add(DoubleDouble.twoProduct(D.z, D.z)).sqrt());
        assertThat(exact(s(ORIGIN, 7, D)).multiply(length).subtract(new BigDecimal(7)).abs())
                .isLessThan(new BigDecimal("1e-29"));
    }

    @Test
    void aSphereBehindTheRayOrBesideItIsMissed() {
        assertThat(s(new Vector3(0, 0, -1.000000000001), 1, new Vector3(0, 0, 1))).isNull();
        assertThat(s(new Vector3(0, 2.000000000001, 5), 2, new Vector3(0, 0, 1))).isNull();
    }

    @Test
    void distancesAgreeWithBigDecimalOnFarSmallAndGiantSpheres() {
        Random random = new Random(11);
        MathContext context = new MathContext(80);
        for (int i = 0; i < 2000; i++) {
            Vector3 D = new Vector3(random.nextGaussian() * 0.3, random.nextGaussian() * 0.3, 1).normalised();
            boolean giant = random.nextBoolean();
            double distance = Math.pow(10, 3 + 13 * random.nextDouble());
            Vector3 C = giant ? new Vector3(0, -distance - 2, 5) : D.scale(distance);
            double r = giant ? distance : distance * 1e-9;
            DoubleDouble s = s(C, r, D);
            // The same roots with 80-digit decimals: beta = D.f, c = f.f - r^2, s = (-beta - sqrt(beta^2 - ac)) / a.
            BigDecimal[] f = {new BigDecimal(-C.x), new BigDecimal(-C.y), new BigDecimal(-C.z)};
            BigDecimal[] d = {new BigDecimal(D.x), new BigDecimal(D.y), new BigDecimal(D.z)};
            BigDecimal a = BigDecimal.ZERO, beta = BigDecimal.ZERO, ff = BigDecimal.ZERO;
            for (int k = 0; k < 3; k++) {
                a = a.add(d[k].multiply(d[k]));
                beta = beta.add(d[k].multiply(f[k]));
                ff = ff.add(f[k].multiply(f[k]));
            }
            BigDecimal c = ff.subtract(new BigDecimal(r).pow(2));
            BigDecimal delta = beta.pow(2).subtract(a.multiply(c));
            if (delta.signum() < 0) {
                assertThat(s).as("case %d: BigDecimal says miss", i).isNull();
                continue;
            }
            BigDecimal near = beta.negate().subtract(delta.sqrt(context)).divide(a, context);
            BigDecimal far = beta.negate().add(delta.sqrt(context)).divide(a, context);
            BigDecimal expected = near.signum() > 0 ? near : far;
            if (expected.signum() <= 0) {
                assertThat(s).as("case %d: BigDecimal says both roots are behind", i).isNull();
                continue;
            }
            assertThat(s).as("case %d: BigDecimal says hit at %s", i, expected).isNotNull();
            // 1e-20: ten thousand times finer than a double (u = 1.1e-16), whatever the cancellation.
            BigDecimal relativeError = exact(s).subtract(expected).abs().divide(expected, context);
            assertThat(relativeError).as("case %d", i).isLessThan(new BigDecimal("1e-20"));
        }
    }

    @Test
    void headOnWithTheLightAtTheCameraEveryTermIsAtItsMaximum() {
        // P = (0, 0, 4), N = L = V = (0, 0, -1): N.L = R.V = 1, d = 4, I = 100 / (4 pi 4^2), white.
        Scene scene = new Scene();
        scene.addObject(new Sphere(new Vector3(0, 0, 5), 1, new Vector3(1, 0, 0)));
        scene.setAmbientLight(new Vector3(0.25));
        scene.setPointLight(new PointLight(ORIGIN, new Vector3(1), 100));
        TruthRenderer.Vec colour = new TruthRenderer(1, 1).trace(scene, new Ray(ORIGIN, new Vector3(0, 0, 1)));
        BigDecimal I = new BigDecimal(100).divide(new BigDecimal(64).multiply(
                new BigDecimal("3.14159265358979323846264338327950288419716939937510")), MathContext.DECIMAL128);
        BigDecimal specular = new BigDecimal(0.8).multiply(I);
        BigDecimal red = new BigDecimal(0.25).add(new BigDecimal(0.8).multiply(I)).add(specular);
        assertThat(exact(colour.x).subtract(red).abs()).isLessThan(new BigDecimal("1e-28"));
        assertThat(exact(colour.y).subtract(specular).abs()).isLessThan(new BigDecimal("1e-28"));
    }

    @Test
    void pixelsTruncateTheExactValue() {
        // 0.1 as a double is just above 1/10, so 255 * 0.1 is just above 25.5: level 25.
        assertThat(TruthRenderer.toRGB(new TruthRenderer.Vec(DoubleDouble.of(0.1), DoubleDouble.of(2),
                DoubleDouble.of(-1)))).isEqualTo(25 << 16 | 255 << 8);
    }
}
