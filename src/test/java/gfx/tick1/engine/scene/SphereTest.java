package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import java.util.Random;
import org.junit.jupiter.api.Test;

class SphereTest {

    private static final Vector3 RED = new Vector3(1, 0, 0);
    private static final Vector3 ORIGIN = new Vector3(0);
    private static final Vector3 FORWARD = new Vector3(0, 0, 1);
    private final Sphere sphere = new Sphere(new Vector3(0, 0, 5), 1, RED);

    @Test
    void aRayThroughTheCentreHitsTheNearSide() {
        RaycastHit hit = sphere.intersectionWith(new Ray(ORIGIN, FORWARD));
        assertThat(hit.getObjectHit()).isSameAs(sphere);
        assertThat(hit.getDistance()).isEqualTo(4);
        assertThat(hit.getLocation()).isEqualTo(new Vector3(0, 0, 4));
        assertThat(hit.getNormal()).isEqualTo(new Vector3(0, 0, -1));
    }

    @Test
    void aRayPassingBesideTheSphereMisses() {
        RaycastHit hit = sphere.intersectionWith(new Ray(ORIGIN, new Vector3(0.3, 0, 1).normalised()));
        assertThat(hit.getObjectHit()).isNull();
        assertThat(hit.getDistance()).isEqualTo(Double.POSITIVE_INFINITY);
    }

    @Test
    void aTangentRayTouchesTheSphereAtOnePoint() {
        // The ray x = 1 grazes the sphere at (1, 0, 5); the discriminant is exactly 0 there.
        RaycastHit hit = sphere.intersectionWith(new Ray(new Vector3(1, 0, 0), FORWARD));
        assertThat(hit.getObjectHit()).isSameAs(sphere);
        assertThat(hit.getDistance()).isEqualTo(5);
        assertThat(hit.getNormal()).isEqualTo(new Vector3(1, 0, 0));
    }

    @Test
    void fromInsideTheSphereTheRayHitsTheFarSide() {
        RaycastHit hit = sphere.intersectionWith(new Ray(new Vector3(0, 0, 5), FORWARD));
        assertThat(hit.getDistance()).isEqualTo(1);
        assertThat(hit.getLocation()).isEqualTo(new Vector3(0, 0, 6));
        assertThat(hit.getNormal()).as("the outward normal, facing away from the camera").isEqualTo(FORWARD);
    }

    @Test
    void aSphereBehindTheRayIsNotHit() {
        RaycastHit hit = sphere.intersectionWith(new Ray(ORIGIN, new Vector3(0, 0, -1)));
        assertThat(hit.getObjectHit()).isNull();
    }

    @Test
    void normalIsTheUnitVectorFromCentreToPoint() {
        assertThat(sphere.getNormalAt(new Vector3(0, 2, 5))).isEqualTo(new Vector3(0, 1, 0));
    }

    @Test
    void everyHitLiesOnTheSurfaceWithAUnitOutwardNormal() {
        Random random = new Random(42);
        int hits = 0;
        for (int i = 0; i < 10_000; i++) {
            Vector3 centre = new Vector3(random.nextGaussian() * 3, random.nextGaussian() * 3,
                    2 + random.nextDouble() * 20);
            double radius = 0.1 + random.nextDouble() * 3;
            Sphere s = new Sphere(centre, radius, RED);
            // Aim near the sphere so that most rays hit, some graze and some miss.
            Vector3 target = centre.add(new Vector3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian())
                    .scale(radius * 0.8));
            Ray ray = new Ray(ORIGIN, target.normalised());
            RaycastHit hit = s.intersectionWith(ray);
            if (hit.getObjectHit() == null) {
                continue;
            }
            hits++;
            assertThat(hit.getDistance()).isPositive();
            assertThat(hit.getLocation().subtract(centre).magnitude()).as("|P - C| for %s and %s", s, ray)
                    .isCloseTo(radius, within(1e-9 * (1 + centre.magnitude())));
            assertThat(hit.getNormal().magnitude()).isCloseTo(1, within(1e-15));
            assertThat(hit.getNormal().dot(hit.getLocation().subtract(centre))).isPositive();
        }
        assertThat(hits).as("the random rays should hit often enough to test something").isGreaterThan(1000);
    }

    @Test
    void phongCoefficientsAreTheTicksConstants() {
        assertThat(sphere.getPhong_kD()).isEqualTo(0.8);
        assertThat(sphere.getPhong_kS()).isEqualTo(0.8);
        assertThat(sphere.getPhong_n()).isEqualTo(10);
    }
}
