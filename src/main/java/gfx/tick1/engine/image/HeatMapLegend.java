package gfx.tick1.engine.image;

import java.awt.image.BufferedImage;
import java.util.Map;
import java.util.function.IntUnaryOperator;

/**
 * The key to a heat map's colours, drawn in a strip below the image: a bar running through the
 * colours from 1 level to 64 levels or more, with ticks at 1, 2, 4 ... 64 and the word LEVELS;
 * for the signed heat map, two bars meeting in the middle, DARKER (64+ to 1 level, in the darker
 * hue) and BRIGHTER (1 to 64+ levels); or, where no pixel differs, the words NO DIFFERENCES.
 *
 * <p>The strip goes below, never over, the image, so a pixel's position in the file is its
 * position in the images compared. The labels are drawn from a small pixel font of our own rather
 * than with a system font: a heat map must not depend on which fonts a machine has installed (a
 * server may have none), and the same difference always gives the same file.
 */
public final class HeatMapLegend {

    /** Height of the strip in pixels. */
    public static final int HEIGHT = 30;
    /** The narrowest image that gets a legend: below that its labels would not fit beside one another. */
    public static final int MIN_WIDTH = 240;

    private static final int BACKGROUND = 0x181818;
    private static final int TEXT = 0xD0D0D0;
    private static final int MARGIN = 12;
    private static final int BAR_TOP = 5;
    private static final int BAR_HEIGHT = 8;
    private static final int LABEL_TOP = 17;
    /** Each glyph (only those the labels use) is 3 x 5 cells, each cell 2 x 2 pixels, with 2 pixels between glyphs. */
    private static final int SCALE = 2;
    private static final int ADVANCE = 4 * SCALE;
    private static final String UNIT = "LEVELS";
    private static final int OCTAVES = 6; // 64 = 2^6
    private static final Map<Character, String> GLYPHS = Map.ofEntries(
            // The 1's flag is on its top row, which the other digits fill: lower, the top looked cut off.
            Map.entry('1', "110010010010111"),
            Map.entry('2', "111001111100111"), Map.entry('3', "111001111001111"),
            Map.entry('4', "101101111001001"), Map.entry('6', "111100111101111"),
            Map.entry('8', "111101111101111"), Map.entry('+', "000010111010000"),
            Map.entry('L', "100100100100111"), Map.entry('E', "111100110100111"),
            Map.entry('V', "101101101101010"), Map.entry('S', "011100010001110"),
            Map.entry('N', "110101101101101"), Map.entry('O', "111101101101111"),
            Map.entry('D', "110101101101110"), Map.entry('I', "111010010010111"),
            Map.entry('F', "111100110100100"), Map.entry('R', "110101110101101"),
            Map.entry('C', "011100100100011"), Map.entry('A', "010101111101101"),
            Map.entry('K', "101110100110101"), Map.entry('B', "110101110101110"),
            Map.entry('G', "011100101101011"), Map.entry('H', "101101111101101"),
            Map.entry('T', "111010010010010"));
    /** What the strip says in place of the key when no pixel differs: a dimmed copy alone reads as a failure. */
    static final String NO_DIFFERENCES = "NO DIFFERENCES";
    private static final String DARKER = "DARKER";
    private static final String BRIGHTER = "BRIGHTER";

    private HeatMapLegend() {
    }

    /**
     * The heat map with the legend strip below it, or the heat map itself when it is narrower
     * than {@link #MIN_WIDTH}. Where no pixel differs, the strip says so instead of showing a key
     * to colours the map does not have.
     */
    public static BufferedImage below(BufferedImage heatMap, boolean anyDifference) {
        BufferedImage image = strip(heatMap, anyDifference);
        if (image == heatMap || !anyDifference) {
            return image;
        }
        int width = image.getWidth(), height = heatMap.getHeight();
        int barStart = MARGIN;
        String lastLabel = (1 << OCTAVES) + "+";
        // Exclusive; room on the right for the last label's right half and the unit.
        int barEnd = width - MARGIN - textWidth(UNIT) - MARGIN - textWidth(lastLabel) / 2;
        int last = barEnd - 1 - barStart;
        bar(image, barStart, barEnd, height, false, ImageDifference::heatColour);
        for (int k = 0; k <= OCTAVES; k++) {
            int x = barStart + (int) Math.round((double) k / OCTAVES * last);
            fill(image, x, height + BAR_TOP + BAR_HEIGHT, 1, 2, TEXT);
            String label = k == OCTAVES ? lastLabel : String.valueOf(1 << k);
            draw(image, label, x - textWidth(label) / 2, height + LABEL_TOP);
        }
        draw(image, UNIT, barEnd + textWidth(lastLabel) / 2 + MARGIN, height + (HEIGHT - 5 * SCALE) / 2);
        return image;
    }

    /**
     * The signed heat map with its key below it, as {@link #below}: on the left DARKER, a bar from 64 levels or more
     * down to 1 in {@link ImageDifference#darkerColour}; on the right BRIGHTER, from 1 up to 64 or more in
     * {@link ImageDifference#heatColour}. The two meet in the middle, where the difference is smallest.
     */
    public static BufferedImage belowSigned(BufferedImage heatMap, boolean anyDifference) {
        BufferedImage image = strip(heatMap, anyDifference);
        if (image == heatMap || !anyDifference) {
            return image;
        }
        int width = image.getWidth(), height = heatMap.getHeight();
        // The two 1s sit apart across the middle, so that they never read as 11.
        int middle = width / 2, gap = 6;
        String most = (1 << OCTAVES) + "+";
        bar(image, MARGIN, middle - gap, height, true, ImageDifference::darkerColour);
        bar(image, middle + gap, width - MARGIN, height, false, ImageDifference::heatColour);
        int top = height + LABEL_TOP;
        draw(image, most, MARGIN, top);
        draw(image, "1", middle - gap - textWidth("1"), top);
        draw(image, "1", middle + gap, top);
        draw(image, most, width - MARGIN - textWidth(most), top);
        // Each word centred between its half's two labels.
        int darkerFrom = MARGIN + textWidth(most), darkerTo = middle - gap - textWidth("1");
        draw(image, DARKER, (darkerFrom + darkerTo - textWidth(DARKER)) / 2, top);
        int brighterFrom = middle + gap + textWidth("1"), brighterTo = width - MARGIN - textWidth(most);
        draw(image, BRIGHTER, (brighterFrom + brighterTo - textWidth(BRIGHTER)) / 2, top);
        return image;
    }

    /**
     * The heat map with an empty strip below it (saying NO DIFFERENCES where nothing differs), or the heat map itself
     * when it is narrower than {@link #MIN_WIDTH}.
     */
    private static BufferedImage strip(BufferedImage heatMap, boolean anyDifference) {
        int width = heatMap.getWidth(), height = heatMap.getHeight();
        if (width < MIN_WIDTH) {
            return heatMap;
        }
        BufferedImage image = new BufferedImage(width, height + HEIGHT, BufferedImage.TYPE_INT_RGB);
        int[] pixels = heatMap.getRGB(0, 0, width, height, null, 0, width);
        image.setRGB(0, 0, width, height, pixels, 0, width);
        fill(image, 0, height, width, HEIGHT, BACKGROUND);
        if (!anyDifference) {
            draw(image, NO_DIFFERENCES, (width - textWidth(NO_DIFFERENCES)) / 2, height + (HEIGHT - 5 * SCALE) / 2);
        }
        return image;
    }

    /**
     * A bar from x = {@code start} to {@code end} (exclusive) in the strip below a map {@code height} high, on the
     * colours' own log scale: position t along it stands for 64^t levels, from its left end, or its right end when
     * {@code fromRight}.
     */
    private static void bar(BufferedImage image, int start, int end, int height, boolean fromRight,
            IntUnaryOperator colour) {
        int last = end - 1 - start;
        for (int x = start; x < end; x++) {
            int along = fromRight ? end - 1 - x : x - start;
            int levels = (int) Math.round(Math.pow(64, (double) along / last));
            fill(image, x, height + BAR_TOP, 1, BAR_HEIGHT, colour.applyAsInt(Math.max(1, levels)));
        }
    }

    private static int textWidth(String text) {
        return text.length() * ADVANCE - (ADVANCE - 3 * SCALE);
    }

    private static void draw(BufferedImage image, String text, int left, int top) {
        for (int i = 0; i < text.length(); i++) {
            String glyph = GLYPHS.getOrDefault(text.charAt(i), ""); // a space, for one
            for (int cell = 0; cell < glyph.length(); cell++) {
                if (glyph.charAt(cell) == '1') {
                    fill(image, left + i * ADVANCE + cell % 3 * SCALE, top + cell / 3 * SCALE, SCALE, SCALE, TEXT);
                }
            }
        }
    }

    private static void fill(BufferedImage image, int x, int y, int width, int height, int rgb) {
        for (int j = y; j < y + height; j++) {
            for (int i = x; i < x + width; i++) {
                image.setRGB(i, j, rgb);
            }
        }
    }
}
