package gfx.tick1.engine.fast;

/**
 * For each sphere, a rectangle of pixels outside which no camera ray can hit it, so that the
 * fast renderer tests it only inside. Ruling out a miss is what costs a ray most of its time
 * when the spheres cover a small part of the frame.
 *
 * <p>A sphere lies inside its axis-aligned box; when the box is wholly in front of the camera
 * (z &gt; 0), the central projection (x/z, y/z) of the box is the convex hull of its eight
 * corners' projections, so their extremes bound every point of the sphere on the image plane.
 * They are mapped to pixels by inverting the camera's formulas and widened by two pixels. A
 * ray two pixels outside a sphere's outline passes it at an angle thousands of times larger
 * than any rounding in the intersection test, so every method (the handout's, the robust one)
 * computes a miss there: skipping the test changes no pixel. A box that reaches z &lt;= 0 (a
 * sphere around or behind the camera) gets the whole frame.
 */
final class ScreenBounds {

    private static final double MARGIN_PIXELS = 2;

    /** Per sphere, the pixel coordinates (inclusive) that its rays may have. */
    final double[] left, right, top, bottom;

    ScreenBounds(FlatScene scene, Frame frame) {
        double widthM = frame.widthM(), heightM = frame.heightM(), xStep = frame.xStep(), yStep = frame.yStep();
        int n = scene.size;
        left = new double[n];
        right = new double[n];
        top = new double[n];
        bottom = new double[n];
        for (int i = 0; i < n; i++) {
            double r = scene.radius[i];
            double near = scene.cz[i] - r;
            // Far enough in front that 1/z and the corners' projections are well conditioned.
            if (!(near > 1e-6 * (Math.abs(scene.cz[i]) + r))) {
                left[i] = top[i] = Double.NEGATIVE_INFINITY;
                right[i] = bottom[i] = Double.POSITIVE_INFINITY;
                continue;
            }
            double uMin = Double.POSITIVE_INFINITY, uMax = Double.NEGATIVE_INFINITY;
            double vMin = Double.POSITIVE_INFINITY, vMax = Double.NEGATIVE_INFINITY;
            for (int corner = 0; corner < 8; corner++) {
                double x = scene.cx[i] + ((corner & 1) == 0 ? -r : r);
                double y = scene.cy[i] + ((corner & 2) == 0 ? -r : r);
                double z = scene.cz[i] + ((corner & 4) == 0 ? -r : r);
                uMin = Math.min(uMin, x / z);
                uMax = Math.max(uMax, x / z);
                vMin = Math.min(vMin, y / z);
                vMax = Math.max(vMax, y / z);
            }
            // The camera: u = (x_step - width_m) / 2 + x x_step, v = (y_step + height_m) / 2 - y y_step.
            left[i] = (uMin - (xStep - widthM) / 2) / xStep - MARGIN_PIXELS;
            right[i] = (uMax - (xStep - widthM) / 2) / xStep + MARGIN_PIXELS;
            top[i] = ((yStep + heightM) / 2 - vMax) / yStep - MARGIN_PIXELS;
            bottom[i] = ((yStep + heightM) / 2 - vMin) / yStep + MARGIN_PIXELS;
        }
    }

    /** Whether the ray through (x, y), in pixels, may hit sphere i. */
    boolean mayHit(int i, double x, double y) {
        return x >= left[i] && x <= right[i] && y >= top[i] && y <= bottom[i];
    }
}
