package gfx.tick1.fast;

import gfx.tick1.render.SamplePattern;

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

    long rays() {
        return (long) width * height * samples.size();
    }
}
