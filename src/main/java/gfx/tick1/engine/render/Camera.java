package gfx.tick1.engine.render;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;

/**
 * The tick's pinhole camera: at the origin, looking along +z (left-handed: x right, y up), with
 * a 45 degree horizontal field of view and an image plane at z = 1.
 */
public final class Camera {

    private static final double FIELD_OF_VIEW_DEGREES = 45;
    private static final Vector3 ORIGIN = new Vector3(0);

    private final double width_m, height_m;
    private final double x_step_m, y_step_m;

    public Camera(int width, int height) {
        double aspectRatio = (double) width / (double) height;
        // The image plane at distance 1 spans 2 tan(fov / 2) across.
        width_m = 2 * Math.tan(Math.toRadians(FIELD_OF_VIEW_DEGREES) / 2);
        height_m = width_m / aspectRatio;
        x_step_m = width_m / width;
        y_step_m = height_m / height;
    }

    /**
     * The unit ray for pixel (x, y), y = 0 being the top row. Across, it passes through the
     * pixel's centre: half a step in from the left edge, then whole steps. Down, the starter
     * code starts at (y_step + height_m) / 2, half a step above the top edge, so every row is
     * cast one step higher than its centre. That is kept on purpose: the handout's figures are
     * reproduced pixel for pixel only with it.
     */
    public Ray castRay(int x, int y) {
        return castRay((double) x, (double) y);
    }

    /**
     * The ray through a point inside a pixel, for anti-aliasing: (x + dx, y + dy) with offsets
     * in pixels. Whole numbers give exactly the rays of {@link #castRay(int, int)}.
     */
    public Ray castRay(double x, double y) {
        double x_pos = (x_step_m - width_m) / 2 + x * x_step_m;
        double y_pos = (y_step_m + height_m) / 2 - y * y_step_m;
        return new Ray(ORIGIN, new Vector3(x_pos, y_pos, 1).normalised());
    }
}
