package gfx.tick1.image;

import java.awt.image.BufferedImage;

/**
 * How two images of the same size differ, channel by channel, in 8-bit levels: the figures the
 * golden-image tests and the {@code compare} command report.
 */
public final class ImageDifference {

    private final BufferedImage expected;
    private final BufferedImage actual;
    private final int differingPixels;
    private final int maxDifference;
    private final int[] maxPerChannel = new int[3];
    private final long[] sumPerChannel = new long[3];
    private int minX = Integer.MAX_VALUE, minY = Integer.MAX_VALUE, maxX = -1, maxY = -1;

    private ImageDifference(BufferedImage expected, BufferedImage actual) {
        this.expected = expected;
        this.actual = actual;
        int differing = 0;
        for (int y = 0; y < expected.getHeight(); y++) {
            for (int x = 0; x < expected.getWidth(); x++) {
                int a = expected.getRGB(x, y), b = actual.getRGB(x, y);
                if ((a & 0xFFFFFF) == (b & 0xFFFFFF)) {
                    continue;
                }
                differing++;
                minX = Math.min(minX, x);
                minY = Math.min(minY, y);
                maxX = Math.max(maxX, x);
                maxY = Math.max(maxY, y);
                for (int c = 0; c < 3; c++) {
                    int shift = 16 - 8 * c;
                    int d = Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF));
                    maxPerChannel[c] = Math.max(maxPerChannel[c], d);
                    sumPerChannel[c] += d;
                }
            }
        }
        this.differingPixels = differing;
        this.maxDifference = Math.max(maxPerChannel[0], Math.max(maxPerChannel[1], maxPerChannel[2]));
    }

    /** Compares two images; throws IllegalArgumentException with both sizes when they differ. */
    public static ImageDifference between(BufferedImage expected, BufferedImage actual) {
        if (expected.getWidth() != actual.getWidth() || expected.getHeight() != actual.getHeight()) {
            throw new IllegalArgumentException("image sizes differ: expected " + expected.getWidth() + " x "
                    + expected.getHeight() + ", actual " + actual.getWidth() + " x " + actual.getHeight());
        }
        return new ImageDifference(expected, actual);
    }

    public int differingPixels() {
        return differingPixels;
    }

    /** How many pixels differ by more than {@code levels} in some channel. */
    public int pixelsDifferingByMoreThan(int levels) {
        int count = 0;
        for (int y = 0; y < expected.getHeight(); y++) {
            for (int x = 0; x < expected.getWidth(); x++) {
                int a = expected.getRGB(x, y), b = actual.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    if (Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF)) > levels) {
                        count++;
                        break;
                    }
                }
            }
        }
        return count;
    }

    /** The largest difference in any channel of any pixel, in levels (0 to 255). */
    public int maxDifference() {
        return maxDifference;
    }

    /** Largest difference of red, green and blue in turn. */
    public int[] maxPerChannel() {
        return maxPerChannel.clone();
    }

    /** Mean absolute difference of red, green and blue in turn, over all pixels. */
    public double[] meanPerChannel() {
        double pixels = (double) expected.getWidth() * expected.getHeight();
        return new double[] {sumPerChannel[0] / pixels, sumPerChannel[1] / pixels, sumPerChannel[2] / pixels};
    }

    /** Peak signal-to-noise ratio in decibels over all channels; infinite for equal images. */
    public double psnr() {
        double squared = 0;
        for (int y = 0; y < expected.getHeight(); y++) {
            for (int x = 0; x < expected.getWidth(); x++) {
                int a = expected.getRGB(x, y), b = actual.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    double d = (a >> shift & 0xFF) - (b >> shift & 0xFF);
                    squared += d * d;
                }
            }
        }
        double mse = squared / (3.0 * expected.getWidth() * expected.getHeight());
        return mse == 0 ? Double.POSITIVE_INFINITY : 10 * Math.log10(255.0 * 255.0 / mse);
    }

    /** The smallest rectangle holding every differing pixel, as "x0,y0 - x1,y1", or "none". */
    public String boundingBox() {
        return differingPixels == 0 ? "none" : minX + "," + minY + " - " + maxX + "," + maxY;
    }

    /**
     * A heat map of the differences over a dimmed grey copy of the expected image: differing
     * pixels run from dark red (1 level) to yellow-white (64 levels or more), so that a one-level
     * truncation error is as visible as a wrong sphere.
     */
    public BufferedImage heatMap() {
        int w = expected.getWidth(), h = expected.getHeight();
        BufferedImage map = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int a = expected.getRGB(x, y), b = actual.getRGB(x, y);
                int d = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    d = Math.max(d, Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF)));
                }
                if (d == 0) {
                    int grey = ((a >> 16 & 0xFF) + (a >> 8 & 0xFF) + (a & 0xFF)) / 12;
                    map.setRGB(x, y, grey << 16 | grey << 8 | grey);
                } else {
                    double t = Math.min(1, Math.log(d) / Math.log(64));
                    int red = (int) (128 + 127 * Math.min(1, 2 * t));
                    int green = (int) (255 * Math.max(0, 2 * t - 1));
                    int blue = (int) (160 * Math.max(0, 3 * t - 2));
                    map.setRGB(x, y, red << 16 | green << 8 | blue);
                }
            }
        }
        return map;
    }

    /** One line for a test failure or the command line. */
    public String summary() {
        int total = expected.getWidth() * expected.getHeight();
        return String.format("%d of %d pixels differ (%.3f%%), max difference %d levels (R %d, G %d, B %d), "
                + "bounding box %s", differingPixels, total, 100.0 * differingPixels / total, maxDifference,
                maxPerChannel[0], maxPerChannel[1], maxPerChannel[2], boundingBox());
    }
}
