package gfx.tick1.engine.image;

import gfx.tick1.engine.io.Counted;
import java.awt.image.BufferedImage;

/**
 * How two images of the same size differ, channel by channel, in 8-bit levels: the figures the
 * golden-image tests and the {@code compare}, {@code diagnose} and {@code grade} commands report.
 *
 * <p>A pixel's difference is the largest difference of its three channels; the histogram of those
 * per-pixel differences answers "how many pixels are within N levels" for any N at once.
 */
public final class ImageDifference {

    private final int width, height;
    private final int[] expected;
    private final int[] actual;
    /** pixelsAt[d] = how many pixels differ by exactly d levels in their worst channel. */
    private final int[] pixelsAt = new int[256];
    private final int[] maxPerChannel = new int[3];
    private final long[] sumPerChannel = new long[3];
    private final long sumOfSquares;
    private int minX = Integer.MAX_VALUE, minY = Integer.MAX_VALUE, maxX = -1, maxY = -1;

    private ImageDifference(int width, int height, int[] expected, int[] actual) {
        this.width = width;
        this.height = height;
        this.expected = expected;
        this.actual = actual;
        long squares = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int a = expected[y * width + x], b = actual[y * width + x];
                int worst = 0;
                for (int c = 0; c < 3; c++) {
                    int d = Math.abs(channel(a, c) - channel(b, c));
                    worst = Math.max(worst, d);
                    maxPerChannel[c] = Math.max(maxPerChannel[c], d);
                    sumPerChannel[c] += d;
                    squares += (long) d * d;
                }
                pixelsAt[worst]++;
                if (worst > 0) {
                    minX = Math.min(minX, x);
                    minY = Math.min(minY, y);
                    maxX = Math.max(maxX, x);
                    maxY = Math.max(maxY, y);
                }
            }
        }
        sumOfSquares = squares;
    }

    /** Compares two images; throws IllegalArgumentException with both sizes when they differ. */
    public static ImageDifference between(BufferedImage expected, BufferedImage actual) {
        if (expected.getWidth() != actual.getWidth() || expected.getHeight() != actual.getHeight()) {
            throw new IllegalArgumentException("image sizes differ: expected " + expected.getWidth() + " x "
                    + expected.getHeight() + ", actual " + actual.getWidth() + " x " + actual.getHeight());
        }
        return new ImageDifference(expected.getWidth(), expected.getHeight(), RgbPixels.of(expected),
                RgbPixels.of(actual));
    }

    /**
     * Compares two images of {@code width} x {@code height} given as their {@link RgbPixels}, so that a caller
     * comparing one image with many reads it once. The difference keeps the arrays, and only reads them: they must
     * not change afterwards.
     */
    public static ImageDifference between(int width, int height, int[] expected, int[] actual) {
        if (expected.length != width * height || actual.length != width * height) {
            throw new IllegalArgumentException("pixel counts differ from " + width + " x " + height + ": expected "
                    + expected.length + ", actual " + actual.length);
        }
        return new ImageDifference(width, height, expected, actual);
    }

    /** Channel 0 = red, 1 = green, 2 = blue of a packed 0xRRGGBB pixel. */
    private static int channel(int rgb, int c) {
        return rgb >> (16 - 8 * c) & 0xFF;
    }

    public int totalPixels() {
        return width * height;
    }

    public int differingPixels() {
        return totalPixels() - pixelsAt[0];
    }

    /** How many pixels differ by at most {@code levels} in every channel. */
    public int pixelsWithin(int levels) {
        int within = 0;
        for (int d = 0; d <= Math.min(levels, 255); d++) {
            within += pixelsAt[d];
        }
        return within;
    }

    /** The share (0 to 1) of pixels that differ by at most {@code levels} in every channel. */
    public double shareWithin(int levels) {
        return (double) pixelsWithin(levels) / totalPixels();
    }

    /** True when no channel of any pixel differs by more than {@code levels}. */
    public boolean isWithin(int levels) {
        return maxDifference() <= levels;
    }

    /** How many pixels differ by more than {@code levels} in some channel. */
    public int pixelsDifferingByMoreThan(int levels) {
        return totalPixels() - pixelsWithin(levels);
    }

    /** The largest difference in any channel of any pixel, in levels (0 to 255). */
    public int maxDifference() {
        return Math.max(maxPerChannel[0], Math.max(maxPerChannel[1], maxPerChannel[2]));
    }

    /** Largest difference of red, green and blue in turn. */
    public int[] maxPerChannel() {
        return maxPerChannel.clone();
    }

    /** Mean absolute difference of red, green and blue in turn, over all pixels. */
    public double[] meanPerChannel() {
        double pixels = totalPixels();
        return new double[] {sumPerChannel[0] / pixels, sumPerChannel[1] / pixels, sumPerChannel[2] / pixels};
    }

    /** Mean absolute difference over all channels of all pixels, in levels. */
    public double meanDifference() {
        return (sumPerChannel[0] + sumPerChannel[1] + sumPerChannel[2]) / (3.0 * totalPixels());
    }

    /** Peak signal-to-noise ratio in decibels over all channels; infinite for equal images. */
    public double psnr() {
        double mse = sumOfSquares / (3.0 * totalPixels());
        return mse == 0 ? Double.POSITIVE_INFINITY : 10 * Math.log10(255.0 * 255.0 / mse);
    }

    /** The smallest rectangle holding every differing pixel, as "x0,y0 - x1,y1", or "none". */
    public String boundingBox() {
        return differingPixels() == 0 ? "none" : minX + "," + minY + " - " + maxX + "," + maxY;
    }

    /**
     * A heat map of the differences over a dimmed grey copy of the expected image: differing
     * pixels run from dark red (1 level) to yellow-white (64 levels or more), so that a one-level
     * truncation error is as visible as a wrong sphere. It says how far a pixel is off, not which
     * way: {@link #signedHeatMap} says that too.
     */
    public BufferedImage heatMap() {
        return map(false);
    }

    /**
     * A heat map that also says which way each pixel is off: where the actual pixel is brighter than the expected
     * one, in {@link #heatColour} (dark red to yellow-white); where it is darker, in {@link #darkerColour} (dark blue
     * to pale cyan). The direction tells mistakes apart that differ by as much: light added where there should be
     * none (the handout's Figure 6a) from light taken away (Figure 6b). Brighter means that the pixel's three
     * channels add up to more; where they add up to the same, the channel that differs most decides.
     */
    public BufferedImage signedHeatMap() {
        return map(true);
    }

    private BufferedImage map(boolean signed) {
        int[] map = new int[width * height];
        for (int i = 0; i < map.length; i++) {
            int a = expected[i], b = actual[i];
            int d = 0, worst = 0, sum = 0;
            for (int c = 0; c < 3; c++) {
                int signedDifference = channel(b, c) - channel(a, c);
                sum += signedDifference;
                if (Math.abs(signedDifference) > d) {
                    d = Math.abs(signedDifference);
                    worst = signedDifference;
                }
            }
            if (d == 0) {
                int grey = (channel(a, 0) + channel(a, 1) + channel(a, 2)) / 12;
                map[i] = grey << 16 | grey << 8 | grey;
            } else {
                boolean darker = signed && (sum < 0 || sum == 0 && worst < 0);
                map[i] = darker ? darkerColour(d) : heatColour(d);
            }
        }
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, map, 0, width);
        return image;
    }

    /**
     * The heat map as a file shows it: with {@link HeatMapLegend}'s key to its colours in a strip
     * below the image when the image is wide enough to hold one. Pixel (x, y) of the image is still
     * pixel (x, y) of the file.
     */
    public BufferedImage heatMapWithLegend() {
        return HeatMapLegend.below(heatMap(), differingPixels() > 0);
    }

    /** The signed heat map as a file shows it, with its two-hued key below it as {@link #heatMapWithLegend}. */
    public BufferedImage signedHeatMapWithLegend() {
        return HeatMapLegend.belowSigned(signedHeatMap(), differingPixels() > 0);
    }

    /**
     * The heat map's colour (0xRRGGBB) for a pixel that differs by {@code levels} (1 to 255) in its
     * worst channel: on a logarithmic scale, so that 1, 2, 4, ... 64 levels are evenly spaced, dark
     * red through red and orange to yellow-white. Legends of the heat map use it too. The signed
     * heat map uses it where the actual pixel is brighter.
     */
    public static int heatColour(int levels) {
        if (levels < 1 || levels > 255) {
            throw new IllegalArgumentException("a difference of " + levels + " levels: must be from 1 to 255");
        }
        double t = Math.min(1, Math.log(levels) / Math.log(64));
        int red = (int) (128 + 127 * Math.min(1, 2 * t));
        int green = (int) (255 * Math.max(0, 2 * t - 1));
        int blue = (int) (160 * Math.max(0, 3 * t - 2));
        return red << 16 | green << 8 | blue;
    }

    /**
     * The signed heat map's colour where the actual pixel is darker by {@code levels} (1 to 255): {@link #heatColour}
     * with red and blue exchanged, the same steps of lightness in the opposite hue, dark blue through blue to pale
     * cyan.
     */
    public static int darkerColour(int levels) {
        int warm = heatColour(levels);
        return (warm & 0xFF) << 16 | warm & 0xFF00 | warm >> 16 & 0xFF;
    }

    /** One line for a test failure or the command line. */
    public String summary() {
        int total = totalPixels(), differing = differingPixels();
        return String.format("%d of %s %s (%.3f%%), max difference %s (R %d, G %d, B %d), bounding box %s", differing,
                Counted.of(total, "pixel"), differing == 1 ? "differs" : "differ", 100.0 * differing / total,
                Counted.of(maxDifference(), "level"), maxPerChannel[0], maxPerChannel[1], maxPerChannel[2],
                boundingBox());
    }
}
