package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import java.util.List;
import java.util.Random;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Properties of ray-sphere intersection that any correct implementation has, checked on
 * generated spheres and rays: origins outside and inside, any direction, unnormalised too.
 *
 * <p>Rounding: the quadratic's coefficients are built from |O - C| and r, so every computed
 * distance carries an error of a few ulps of that scale L = |O - C| + r. The tolerance 1e-9 L
 * is a million ulps of L: loose enough for any double-precision solver, tight enough to catch
 * a wrong root or a wrong formula, whose errors are of the order of L itself.
 */
class SphereIntersectionPropertiesTest {

    private static final Vector3 COLOUR = new Vector3(1, 0, 0);

    /** One generated sphere and ray, reproducible from its seed. */
    record Case(long seed, Sphere sphere, Ray ray) {
        static Case generate(long seed) {
            Random random = new Random(seed);
            Sphere sphere = new Sphere(vector(random, 50), 0.01 + random.nextDouble() * 20, COLOUR);
            Vector3 origin = random.nextInt(4) == 0
                    ? SphereGeometry.centre(sphere).add(vector(random, 1).normalised()
                            .scale(SphereGeometry.radius(sphere) * random.nextDouble()))
                    : vector(random, 50);
            // Aim near the sphere half of the time, so that hits, grazes and misses all occur.
            Vector3 direction = random.nextBoolean()
                    ? SphereGeometry.centre(sphere).add(vector(random, SphereGeometry.radius(sphere))).subtract(origin)
                    : vector(random, 1);
            return new Case(seed, sphere, new Ray(origin, direction.scale(0.1 + random.nextDouble() * 10)));
        }

        double scale() {
            return ray.getOrigin().subtract(SphereGeometry.centre(sphere)).magnitude() + SphereGeometry.radius(sphere);
        }

        boolean originOutside() {
            return ray.getOrigin().subtract(SphereGeometry.centre(sphere)).magnitude()
                    > SphereGeometry.radius(sphere) * (1 + 1e-9);
        }

        @Override
        public String toString() {
            return "seed " + seed;
        }
    }

    private static Vector3 vector(Random random, double size) {
        return new Vector3(random.nextDouble() * 2 - 1, random.nextDouble() * 2 - 1, random.nextDouble() * 2 - 1)
                .scale(size);
    }

    static Stream<Case> cases() {
        return IntStream.range(0, 250).mapToObj(seed -> Case.generate(seed));
    }

    /**
     * The properties below each skip the cases they do not speak of (a miss, an origin inside);
     * this keeps every one of them speaking of many cases, so that none can pass by testing nothing.
     */
    @Test
    void theCasesIncludeManyHitsMissesAndOriginsInsideAndOutside() {
        List<Case> all = cases().collect(Collectors.toList());
        long hits = all.stream().filter(c -> c.sphere().intersectionWith(c.ray()).getObjectHit() != null).count();
        long outside = all.stream().filter(Case::originOutside).count();
        long inside = all.stream()
                .filter(c -> c.ray().getOrigin().subtract(SphereGeometry.centre(c.sphere())).magnitude()
                        <= SphereGeometry.radius(c.sphere()) * (1 - 1e-6))
                .count();
        assertThat(hits).as("hits").isGreaterThan(50);
        assertThat(all.size() - hits).as("misses").isGreaterThan(50);
        assertThat(outside).as("origins outside").isGreaterThan(50);
        assertThat(inside).as("origins well inside").isGreaterThan(20);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void aHitLiesOnTheSurfaceAndNoNearerPointOfTheRayIsInside(Case c) {
        RaycastHit hit = c.sphere().intersectionWith(c.ray());
        if (hit.getObjectHit() == null) {
            return;
        }
        Vector3 centre = SphereGeometry.centre(c.sphere());
        double tolerance = 1e-9 * c.scale();
        assertThat(hit.getDistance()).as("%s", c).isPositive();
        assertThat(hit.getLocation().subtract(centre).magnitude() - SphereGeometry.radius(c.sphere())).as("%s", c)
                .isBetween(-tolerance, tolerance);
        if (c.originOutside()) {
            // The nearest root: halfway to the hit the ray has not yet entered the sphere.
            Vector3 halfway = c.ray().evaluateAt(hit.getDistance() / 2);
            assertThat(halfway.subtract(centre).magnitude()).as("%s", c)
                    .isGreaterThanOrEqualTo(SphereGeometry.radius(c.sphere()) - tolerance);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void aRayFiredFromAHitAlongTheNormalNeverHitsTheSphereAgainInFrontOfIt(Case c) {
        RaycastHit hit = c.sphere().intersectionWith(c.ray());
        if (hit.getObjectHit() == null) {
            return;
        }
        Ray outwards = new Ray(hit.getLocation(), hit.getNormal());
        RaycastHit again = c.sphere().intersectionWith(outwards);
        // At most the start point itself, found again through rounding.
        assertThat(again.getObjectHit() == null || again.getDistance() <= 1e-9 * c.scale())
                .as("%s: hit again at distance %s", c, again.getDistance()).isTrue();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void aRayFromOutsidePointingAwayFromTheSphereMisses(Case c) {
        Vector3 away = c.ray().getOrigin().subtract(SphereGeometry.centre(c.sphere()));
        if (!c.originOutside()) {
            return;
        }
        // Any direction with a positive component along (O - C) moves away from every point of the sphere.
        Vector3 forward = c.ray().getDirection();
        Vector3 direction = away.add(forward.scale(0.5 * away.magnitude() / forward.magnitude()));
        assertThat(c.sphere().intersectionWith(new Ray(c.ray().getOrigin(), direction)).getObjectHit()).as("%s", c)
                .isNull();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void aRayFromInsideTheSphereAlwaysHitsItsSurface(Case c) {
        double fromCentre = c.ray().getOrigin().subtract(SphereGeometry.centre(c.sphere())).magnitude();
        if (fromCentre > SphereGeometry.radius(c.sphere()) * (1 - 1e-6)) {
            return; // outside, or too near the surface to say which side rounding puts it
        }
        RaycastHit hit = c.sphere().intersectionWith(c.ray());
        assertThat(hit.getObjectHit()).as("%s", c).isSameAs(c.sphere());
        double tolerance = 1e-9 * c.scale();
        double distance = hit.getLocation().subtract(SphereGeometry.centre(c.sphere())).magnitude();
        assertThat(distance - SphereGeometry.radius(c.sphere()))
                .as("%s", c).isBetween(-tolerance, tolerance);
    }
}
