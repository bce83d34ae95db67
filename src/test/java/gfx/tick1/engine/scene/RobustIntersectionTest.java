package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.math.DoubleDouble;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.TruthRenderer;
import java.util.Random;
import org.junit.jupiter.api.Test;

class RobustIntersectionTest {

    private static final Vector3 ORIGIN = new Vector3(0);
    private static final Vector3 GREY = new Vector3(0.5);
    private static final double U = 0x1p-53;

    private static RaycastHit hit(Intersection method, Vector3 centre, double radius, Vector3 direction) {
        return method.find(new Sphere(centre, radius, GREY), new Ray(ORIGIN, direction));
    }

    /** |s - exact| / exact, with the exact s from the truth renderer. */
    private static double relativeError(RaycastHit hit, Sphere sphere, Ray ray) {
        DoubleDouble exact = TruthRenderer.hitDistance(sphere, ray);
        return Math.abs(DoubleDouble.of(hit.getDistance()).subtract(exact).doubleValue() / exact.doubleValue());
    }

    @Test
    void straightDownOntoAGiantFloorTheHitIsExact() {
        // The floor's top is 2 below the camera; the exact s is 2.
        assertThat(hit(Intersection.ROBUST, new Vector3(0, -1e16, 0), 1e16 - 2, new Vector3(0, -1, 0)).getDistance())
                .isEqualTo(2);
    }

    @Test
    void aslantOntoAGiantFloorTheHandoutsDistanceIsOffByPercentsAndTheRobustOneIsNot() {
        Sphere floor = new Sphere(new Vector3(0, -1e16, 5), 1e16 - 2, GREY);
        Ray ray = new Ray(ORIGIN, new Vector3(0.1, -0.3, 1).normalised());
        assertThat(relativeError(Intersection.HANDOUT.find(floor, ray), floor, ray)).isGreaterThan(0.01);
        assertThat(relativeError(Intersection.ROBUST.find(floor, ray), floor, ray)).isLessThan(4 * U);
    }

    @Test
    void aSmallSphereFarAwayOnTheRayIsHitAtItsNearSide() {
        Vector3 D = new Vector3(0.2, -0.1, 1).normalised();
        Sphere sphere = new Sphere(D.scale(1e12), 1000, GREY);
        Ray ray = new Ray(ORIGIN, D);
        RaycastHit hit = Intersection.ROBUST.find(sphere, ray);
        assertThat(hit.isHit()).isTrue();
        assertThat(relativeError(hit, sphere, ray)).isLessThan(4 * U);
    }

    /** The default's guarantee: the handout's s only where it is within TOLERANCE, else the stable one. */
    @Test
    void onHardRaysTheDefaultDistanceIsWithinTheToleranceAndTheStableOneWithinAFewUlps() {
        Random random = new Random(5);
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            Vector3 D = new Vector3(random.nextGaussian() * 0.3, random.nextGaussian() * 0.3, 1).normalised();
            double scale = Math.pow(10, 3 + 13 * random.nextDouble());
            Sphere sphere = random.nextBoolean()
                    ? new Sphere(new Vector3(0, -scale - 2, 5), scale, GREY) // a floor 2 below the camera
                    : new Sphere(D.scale(scale), scale * 1e-9, GREY);          // a far sphere on the ray
            Ray ray = new Ray(ORIGIN, D);
            RaycastHit hit = Intersection.ROBUST.find(sphere, ray);
            RaycastHit stable = Intersection.STABLE.find(sphere, ray);
            boolean exactHit = TruthRenderer.hitDistance(sphere, ray) != null;
            assertThat(hit.isHit()).as("%s, %s", sphere, ray).isEqualTo(exactHit);
            assertThat(stable.isHit()).as("%s, %s", sphere, ray).isEqualTo(exactHit);
            if (exactHit) {
                hits++;
                assertThat(relativeError(hit, sphere, ray)).as("%s, %s", sphere, ray)
                        .isLessThan(RobustIntersection.TOLERANCE);
                assertThat(relativeError(stable, sphere, ray)).as("%s, %s", sphere, ray).isLessThan(8 * U);
            }
        }
        assertThat(hits).isGreaterThan(10_000);
    }

    @Test
    void fromAPointOnTheSurfaceTheRayHitsTheFarSideNotItsOrigin() {
        RaycastHit hit = hit(Intersection.ROBUST, new Vector3(0, 0, 3), 3, new Vector3(0, 0, 1));
        assertThat(hit.getDistance()).isEqualTo(6);
    }

    @Test
    void alongTheTangentPlaneFromAPointOnTheSurfaceThereIsNoHit() {
        // beta = 0, Delta = 0, c = 0: both roots are 0, and s = 0 is not a hit.
        assertThat(hit(Intersection.ROBUST, new Vector3(0, 0, 3), 3, new Vector3(1, 0, 0)).isHit()).isFalse();
    }

    @Test
    void aSphereJustBehindTheCameraIsNotHit() {
        assertThat(hit(Intersection.ROBUST, new Vector3(0, 0, -1.000000000001), 1, new Vector3(0, 0, 1)).isHit())
                .isFalse();
    }

    @Test
    void fromInsideTheRayHitsTheFarSide() {
        RaycastHit hit = hit(Intersection.ROBUST, new Vector3(0, 0, 1), 4, new Vector3(0, 0, 1));
        assertThat(hit.getDistance()).isEqualTo(5);
        assertThat(hit.getNormal()).isEqualTo(new Vector3(0, 0, 1));
    }

    @Test
    void differenceOfProductsIsAccurateWhenTheProductsCancel() {
        // 0.1 * 0.3 - 0.3 * 0.1 is exactly 0 however it is rounded; (1 + u)(1 - u) - 1 = -u^2 exactly.
        assertThat(RobustIntersection.differenceOfProducts(0.1, 0.3, 0.3, 0.1)).isZero();
        assertThat(RobustIntersection.differenceOfProducts(1 + 2 * U, 1 - 2 * U, 1, 1)).isEqualTo(-4 * U * U);
    }

    @Test
    void theStableVariantAlsoRoundsDifferentlyFromTheHandoutOnOrdinaryRays() {
        // Why the default keeps the handout's s where it can: the stable formula's s is as good,
        // but a different double, on most ordinary hits.
        Random random = new Random(9);
        int differ = 0;
        for (int i = 0; i < 1000; i++) {
            Vector3 D = new Vector3(random.nextGaussian() * 0.1, random.nextGaussian() * 0.1, 1).normalised();
            Sphere sphere = new Sphere(new Vector3(0, 0, 5 + random.nextDouble()), 1, GREY);
            Ray ray = new Ray(ORIGIN, D);
            double stable = Intersection.STABLE.find(sphere, ray).getDistance();
            double handout = Intersection.HANDOUT.find(sphere, ray).getDistance();
            differ += stable != handout ? 1 : 0;
            assertThat(Intersection.ROBUST.find(sphere, ray).getDistance()).isEqualTo(handout);
        }
        assertThat(differ).as("hits where the stable and the handout's s differ").isGreaterThan(100);
    }
}
