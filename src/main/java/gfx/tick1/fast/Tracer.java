package gfx.tick1.fast;

/**
 * One thread's tracing state: the fast renderer's kernel. Each thread has its own, with its row
 * buffers, and traces whole rows with it.
 */
interface Tracer {

    /** Traces row y into {@code pixels} from {@code offset} on, as packed 0xRRGGBB. */
    void row(int y, int[] pixels, int offset);

    /**
     * Packs a row's colours, the sums of its samples' colours scaled by {@code scale}, as
     * 0xRRGGBB into {@code pixels} from {@code offset} on: {@code Vector3.toByte} per channel, in
     * two steps, the clamped channel times 255 in doubles ({@code bytes}, three arrays of the
     * row's width to work in), then the cast to int. The first step vectorises; in one loop
     * with the cast, Math.min and Math.max would run a pixel at a time.
     */
    static void packRow(double[] red, double[] green, double[] blue, double scale, double[][] bytes, int[] pixels,
            int offset) {
        clampedChannel(bytes[0], red, scale);
        clampedChannel(bytes[1], green, scale);
        clampedChannel(bytes[2], blue, scale);
        double[] byteRed = bytes[0], byteGreen = bytes[1], byteBlue = bytes[2];
        for (int x = 0; x < byteRed.length; x++) {
            pixels[offset + x] = (int) byteRed[x] << 16 | (int) byteGreen[x] << 8 | (int) byteBlue[x];
        }
    }

    /** 255 max(0, min(1, scale * sum)): Vector3.toByte before its cast. */
    private static void clampedChannel(double[] into, double[] sum, double scale) {
        for (int x = 0; x < into.length; x++) {
            into[x] = 255 * Math.max(0, Math.min(1, scale * sum[x]));
        }
    }
}
