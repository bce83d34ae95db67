package gfx.tick1.engine.render;

/**
 * Where the samples of one pixel go when anti-aliasing: the same offsets for every pixel and
 * every run, so an anti-aliased image is as repeatable as the faithful one.
 *
 * <p>The offsets follow Roberts' R2 sequence (a rank-1 lattice from the plastic number,
 * "The unreasonable effectiveness of quasirandom sequences", 2018): point i is
 * frac(1/2 + i (1/p, 1/p^2)) - 1/2 for p^3 = p + 1. Any prefix is spread evenly over the pixel,
 * so every sample count works, and point 0 is the pixel's own ray, so one sample is exactly the
 * faithful image.
 */
public final class SamplePattern {

    /** The plastic number, the real root of p^3 = p + 1. */
    private static final double PLASTIC = 1.32471795724474602596;
    private static final double A1 = 1 / PLASTIC, A2 = 1 / (PLASTIC * PLASTIC);

    /** The most samples a pixel may take. */
    public static final int MAX_SAMPLES = 1024;

    private final double[] dx, dy;

    public SamplePattern(int samples) {
        if (samples < 1 || samples > MAX_SAMPLES) {
            throw new IllegalArgumentException("samples must be from 1 to " + MAX_SAMPLES + ", not " + samples);
        }
        dx = new double[samples];
        dy = new double[samples];
        for (int i = 0; i < samples; i++) {
            dx[i] = fraction(0.5 + i * A1) - 0.5;
            dy[i] = fraction(0.5 + i * A2) - 0.5;
        }
    }

    private static double fraction(double v) {
        return v - Math.floor(v);
    }

    public int size() {
        return dx.length;
    }

    /** Horizontal offset of sample i, in pixels, in [-1/2, 1/2). */
    public double dx(int i) {
        return dx[i];
    }

    /** Vertical offset of sample i, in pixels, in [-1/2, 1/2). */
    public double dy(int i) {
        return dy[i];
    }
}
