package gfx.tick1.engine.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import org.junit.jupiter.api.Test;

class CameraTest {

    private static final int W = 640, H = 480;
    private static final double HALF_WIDTH = Math.tan(Math.toRadians(22.5));
    private final Camera camera = new Camera(W, H);

    @Test
    void everyRayStartsAtTheOriginWithAUnitDirection() {
        for (int[] p : new int[][] {{0, 0}, {W - 1, 0}, {0, H - 1}, {W - 1, H - 1}, {123, 456}}) {
            Ray ray = camera.castRay(p[0], p[1]);
            assertThat(ray.getOrigin()).isEqualTo(new Vector3(0));
            assertThat(ray.getDirection().magnitude()).as("|D| at %d,%d", p[0], p[1]).isCloseTo(1, within(1e-15));
        }
    }

    @Test
    void topLeftRayFollowsTheStarterCodesFormula() {
        // x: half a step in from the left edge, the pixel's centre. y: (y_step + height_m) / 2, half
        // a step ABOVE the top edge: the starter camera's rows sit one step higher than pixel
        // centres, and the handout's figures are only reproduced with that quirk kept.
        double step = 2 * HALF_WIDTH / W;
        Vector3 expected = new Vector3(-HALF_WIDTH + step / 2, HALF_WIDTH * H / W + step / 2, 1).normalised();
        Vector3 actual = camera.castRay(0, 0).getDirection();
        assertThat(actual.subtract(expected).magnitude()).as("%s vs %s", actual, expected).isLessThan(1e-15);
    }

    @Test
    void horizontalFieldOfViewIs45DegreesFromEdgeToEdge() {
        // The left edge of pixel 0 and the right edge of pixel W-1 are half a step beyond the centres.
        Vector3 left = camera.castRay(0, H / 2).getDirection();
        Vector3 right = camera.castRay(W - 1, H / 2).getDirection();
        double halfStep = HALF_WIDTH / W;
        double leftEdge = Math.atan(-left.x / left.z + halfStep);
        double rightEdge = Math.atan(right.x / right.z + halfStep);
        assertThat(Math.toDegrees(leftEdge + rightEdge)).isCloseTo(45, within(1e-9));
    }

    @Test
    void pixelsAreSquareSoRowsAndColumnsAreOneStepApart() {
        double xStep = slopeX(1, 0) - slopeX(0, 0);
        double yStep = slopeY(0, 0) - slopeY(0, 1);
        assertThat(yStep).isCloseTo(xStep, within(1e-15));
        assertThat(slopeX(W - 1, 0) - slopeX(0, 0)).isCloseTo((W - 1) * xStep, within(1e-13));
        assertThat(slopeY(0, 0) - slopeY(0, H - 1)).isCloseTo((H - 1) * xStep, within(1e-13));
    }

    private double slopeX(int x, int y) {
        Vector3 d = camera.castRay(x, y).getDirection();
        return d.x / d.z;
    }

    private double slopeY(int x, int y) {
        Vector3 d = camera.castRay(x, y).getDirection();
        return d.y / d.z;
    }

    @Test
    void yZeroIsTheTopRowAndXGrowsToTheRight() {
        assertThat(camera.castRay(10, 0).getDirection().y).isPositive();
        assertThat(camera.castRay(10, H - 1).getDirection().y).isNegative();
        assertThat(camera.castRay(0, 10).getDirection().x).isNegative();
        assertThat(camera.castRay(W - 1, 10).getDirection().x).isPositive();
    }

    @Test
    void columnsMirrorAboutTheCentreAndRowsAboutTheStarterCodesShiftedCentre() {
        // Column x mirrors column W-1-x; with the one-step vertical shift, row y mirrors row H+1-y.
        Vector3 a = camera.castRay(100, 50).getDirection();
        Vector3 b = camera.castRay(W - 1 - 100, H + 1 - 50).getDirection();
        assertThat(a.x).isCloseTo(-b.x, within(1e-15));
        assertThat(a.y).isCloseTo(-b.y, within(1e-15));
        assertThat(a.z).isCloseTo(b.z, within(1e-15));
    }
}
