package gfx.tick1.grade.report;

import gfx.tick1.image.ImageDifference;

/**
 * The heat maps' key on the feedback pages, as HTML and as text (the PNG files carry a strip of
 * their own, drawn by the image package): a swatch of {@link ImageDifference#heatColour} at each
 * doubling of the difference, and the dimmed grey that marks pixels equal to the expected image.
 */
final class HeatMapKey {

    /** The differences shown, in levels; the heat map's scale ends at 64, brighter is not possible. */
    private static final int[] LEVELS = {1, 2, 4, 8, 16, 32, 64};

    private HeatMapKey() {
    }

    static String html() {
        StringBuilder out = new StringBuilder("<figure class=\"legend\"><figcaption>Heat map colours: how far a "
                + "pixel of yours is from the expected one, in its worst colour channel (levels of 0 to 255)"
                + "</figcaption><ul>\n<li><span class=\"swatch\" "
                + "style=\"background:linear-gradient(90deg,#000,#3f3f3f)\">"
                + "</span>same (a dimmed grey copy of the expected image)</li>\n");
        for (int levels : LEVELS) {
            out.append(String.format("<li><span class=\"swatch\" style=\"background:#%06x\"></span>%s</li>%n",
                    ImageDifference.heatColour(levels), describe(levels)));
        }
        return out.append("</ul></figure>\n").toString();
    }

    static String text() {
        return "Heat map colours: pixels equal to the expected image are a dimmed grey copy of it; differing "
                + "pixels run from dark red (1 level) through red and orange to yellow-white (64 levels or more).";
    }

    private static String describe(int levels) {
        return levels == 1 ? "1 level off" : levels == LEVELS[LEVELS.length - 1] ? levels + " levels or more"
                : levels + " levels";
    }
}
