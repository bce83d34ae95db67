package gfx.tick1.engine.fast;

import gfx.tick1.engine.render.SamplePattern;

/**
 * The frame being rendered: its size, its samples, and the Camera's image plane for it, with the
 * Camera's arithmetic step for step so that every tracer casts the readable code's rays.
 */
record Frame(int width, int height, SamplePattern samples, double widthM, double heightM, double xStep, double yStep) {

    static Frame of(int width, int height, SamplePattern samples) {
        double aspectRatio = (double) width / (double) height;
        double widthM = 2 * Math.tan(Math.toRadians(45) / 2);
        double heightM = widthM / aspectRatio;
        return new Frame(width, height, samples, widthM, heightM, widthM / width, heightM / height);
    }

    /** The image plane's x through pixel column x (plus a sample's offset): the Camera's x_pos. */
    double planeX(double x) {
        return (xStep - widthM) / 2 + x * xStep;
    }

    /** The image plane's y through row y (plus a sample's offset): the Camera's y_pos. */
    double planeY(double y) {
        return (yStep + heightM) / 2 - y * yStep;
    }

    /**
     * The Camera's unit ray directions through (x + offsetX, sampleY) for every column x, step
     * for step: {@code castRay} and {@code Vector3.normalised}. {@code column} holds x as a
     * double; reading it from memory rather than using the loop counter lets C2 vectorise the
     * loop (JDK 17 cannot vectorise a use of the counter as a number), which makes this pass
     * much faster (docs/benchmark.md).
     */
    void rayDirections(double offsetX, double sampleY, double[] column, double[] dx, double[] dy, double[] dz) {
        double py = planeY(sampleY), pySquared = py * py;
        for (int x = 0; x < width; x++) {
            double px = planeX(column[x] + offsetX);
            double length = Math.sqrt(px * px + pySquared + 1 * 1);
            dx[x] = px / length;
            dy[x] = py / length;
            dz[x] = 1 / length;
        }
    }

    /** The column numbers 0, 1, ..., width - 1 as doubles, for {@link #rayDirections}. */
    double[] columns() {
        double[] column = new double[width];
        for (int x = 0; x < width; x++) {
            column[x] = x;
        }
        return column;
    }
}
