package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.engine.image.RgbPixels;
import java.awt.image.BufferedImage;
import java.util.Arrays;

/** Whether two images have the same pixels: the pass path needs no difference figures. */
final class Pixels {

    private Pixels() {
    }

    /** Whether {@code a} and {@code b} have the same size and the same colour at every pixel. */
    static boolean same(BufferedImage a, BufferedImage b) {
        if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) {
            return false;
        }
        return Arrays.equals(RgbPixels.of(a), RgbPixels.of(b));
    }
}
