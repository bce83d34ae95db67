package gfx.tick1.command.shared.grader.grading;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
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
        return Arrays.equals(rgb(a), rgb(b));
    }

    private static int[] rgb(BufferedImage image) {
        if (image.getType() == BufferedImage.TYPE_INT_RGB
                && image.getRaster().getDataBuffer() instanceof DataBufferInt ints
                && ints.getNumBanks() == 1 && ints.getData().length == image.getWidth() * image.getHeight()) {
            return ints.getData();
        }
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }
}
