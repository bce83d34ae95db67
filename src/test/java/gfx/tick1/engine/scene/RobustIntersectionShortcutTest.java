package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.Camera;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The robust method's quick acceptance ({@link RobustIntersection#handoutCertainlyAccurate}) is a
 * shortcut, not a second opinion: with it and without it, the decision must be the same on
 * every input, however hard, and it must actually be taken on ordinary hits.
 */
class RobustIntersectionShortcutTest {

    /** A direction D and an offset f = O - C with a radius, as the method sees them. */
    private record Case(double dx, double dy, double dz, double fx, double fy, double fz, double r) {
    }

    private static double decide(Case c, boolean quickAccept) {
        double a = c.dx * c.dx + c.dy * c.dy + c.dz * c.dz;
        return RobustIntersection.nearestRoot(c.dx, c.dy, c.dz, a,
                RobustIntersection.Offset.of(c.fx, c.fy, c.fz, c.r), true, quickAccept);
    }

    /** A unit direction from the origin towards a point. */
    private static Case aimed(Vector3 target, Vector3 centre, double r) {
        Vector3 d = target.normalised();
        return new Case(d.x, d.y, d.z, 0 - centre.x, 0 - centre.y, 0 - centre.z, r);
    }

    private static List<Case> hardCases(Random random) {
        List<Case> cases = new ArrayList<>();
        for (int i = 0; i < 4000; i++) {
            double r = Math.pow(10, -3 + 19 * random.nextDouble());
            double distance = r * Math.pow(10, -1 + 17 * random.nextDouble()) * (random.nextBoolean() ? 1 : 1.0000001);
            Vector3 direction = new Vector3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian())
                    .normalised();
            Vector3 centre = direction.scale(distance);
            // Aim at the silhouette, inside it or just outside it, at scales down to an ulp.
            Vector3 side = direction.cross(new Vector3(0.3, 1, 0.1)).normalised();
            double offset = r * (1 + (random.nextDouble() - 0.5) * Math.pow(10, -16 * random.nextDouble()));
            cases.add(aimed(centre.add(side.scale(offset * random.nextDouble() * 1.2)), centre, r));
            cases.add(aimed(centre.add(side.scale(offset)), centre, r));
        }
        for (double R = 1e6; R <= 1e16; R *= 10) {
            for (int i = 0; i < 200; i++) {
                // A giant floor just below the camera, seen downwards.
                Vector3 centre = new Vector3(0, -R - 1 - random.nextDouble(), 5);
                cases.add(aimed(new Vector3(random.nextGaussian(), -0.05 - random.nextDouble(), 1), centre, R));
            }
        }
        return cases;
    }

    @Test
    void theDecisionIsTheSameWithAndWithoutTheShortcutOnHardInputs() {
        int differing = 0, stable = 0;
        String first = null;
        for (Case c : hardCases(new Random(7))) {
            double slow = decide(c, false), quick = decide(c, true);
            stable += slow > 0 ? 1 : 0; // a hit that the stable formula, not the handout's, decided
            if (Double.compare(slow, quick) != 0) {
                differing++;
                first = first != null ? first : c + ": " + slow + " without, " + quick + " with the shortcut";
            }
        }
        assertThat(differing).as("decisions changed by the shortcut, first: %s", first).isZero();
        assertThat(stable).as("hard inputs on which the handout's formula is not trusted").isGreaterThan(100);
    }

    @Test
    void theShortcutDecidesAlmostEveryOrdinaryHitAndAgreesWithTheSlowTest() {
        Random random = new Random(11);
        Camera camera = new Camera(64, 48);
        int hits = 0, quick = 0;
        for (int scene = 0; scene < 200; scene++) {
            Vector3 centre = new Vector3(random.nextGaussian(), random.nextGaussian(), 3 + 8 * random.nextDouble());
            double r = 0.2 + 1.5 * random.nextDouble();
            for (int y = 0; y < 48; y += 3) {
                for (int x = 0; x < 64; x += 3) {
                    Vector3 d = camera.castRay(x, y).getDirection();
                    Case c = new Case(d.x, d.y, d.z, 0 - centre.x, 0 - centre.y, 0 - centre.z, r);
                    double slow = decide(c, false);
                    assertThat(decide(c, true)).as("%s", c).isEqualTo(slow);
                    if (slow == RobustIntersection.HANDOUT_IS_ACCURATE) {
                        hits++;
                        quick += quickAccepts(c) ? 1 : 0;
                    }
                }
            }
        }
        assertThat(hits).isGreaterThan(1000);
        assertThat((double) quick / hits).as("share of ordinary hits the shortcut decides").isGreaterThan(0.95);
    }

    /** The shortcut's own verdict, from the quantities nearestRoot gives it. */
    private static boolean quickAccepts(Case c) {
        double a = c.dx * c.dx + c.dy * c.dy + c.dz * c.dz;
        RobustIntersection.Offset offset = RobustIntersection.Offset.of(c.fx, c.fy, c.fz, c.r);
        double roughBeta = RobustIntersection.roughBeta(c.dx, c.dy, c.dz, offset);
        double betaAbs = RobustIntersection.betaAbs(c.dx, c.dy, c.dz, offset);
        double E = RobustIntersection.discriminantBound(a, betaAbs, offset);
        double roughDelta = RobustIntersection.roughDelta(a, roughBeta, offset);
        return RobustIntersection.quickAccepts(a, roughBeta, betaAbs, roughDelta, E);
    }
}
