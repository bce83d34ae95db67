package gfx.tick1.command.shared.grader.report;

import gfx.tick1.engine.image.ImageDifference;
import java.util.function.IntUnaryOperator;

/**
 * The heat maps' key on the feedback pages, as HTML and as text (the PNG files carry a strip of
 * their own, drawn by the image package): the maps are signed, so a swatch of
 * {@link ImageDifference#heatColour} (yours brighter) and one of {@link ImageDifference#darkerColour}
 * (yours darker) at each doubling of the difference, and the dimmed grey that marks pixels equal to
 * the expected image.
 */
final class HeatMapKey {

    /** The differences shown, in levels; the heat map's scale ends at 64, brighter is not possible. */
    private static final int[] LEVELS = {1, 2, 4, 8, 16, 32, 64};

    private HeatMapKey() {
    }

    static String html() {
        StringBuilder out = new StringBuilder("<figure class=\"legend\"><figcaption>Heat map colours: how far a "
                + "pixel of yours is from the expected one, in its worst colour channel (levels of 0 to 255), and "
                + "which way: warm colours where yours is brighter, cool ones where it is darker"
                + "</figcaption><ul>\n<li><span class=\"swatch\" "
                + "style=\"background:linear-gradient(90deg,#000,#3f3f3f)\">"
                + "</span>same (a dimmed grey copy of the expected image)</li>\n");
        swatches(out, ImageDifference::heatColour, "brighter");
        swatches(out, ImageDifference::darkerColour, "darker");
        return out.append("</ul></figure>\n").toString();
    }

    private static void swatches(StringBuilder out, IntUnaryOperator colour, String way) {
        for (int levels : LEVELS) {
            out.append(String.format("<li><span class=\"swatch\" style=\"background:#%06x\"></span>%s %s</li>%n",
                    colour.applyAsInt(levels), way, describe(levels)));
        }
    }

    static String text() {
        return "Heat map colours: pixels equal to the expected image are a dimmed grey copy of it. Where your pixel "
                + "is brighter, it runs from dark red (1 level) through red and orange to yellow-white (64 levels or "
                + "more); where yours is darker, from dark blue (1 level) through blue to pale cyan (64 or more).";
    }

    private static String describe(int levels) {
        return levels == 1 ? "by 1 level" : levels == LEVELS[LEVELS.length - 1] ? "by " + levels + " levels or more"
                : "by " + levels + " levels";
    }
}
