package gfx.tick1.command.shared.diagnosis;

import gfx.tick1.engine.image.RgbPixels;
import java.util.Arrays;

/**
 * The pixels where at least one entry of the catalogue draws a sphere: the only pixels that can
 * tell entries apart, as every entry draws the background everywhere else. Ranking on the whole
 * frame would let the background, which every entry shares, outweigh the spheres (on tick1.xml
 * it is two thirds of the frame).
 *
 * @param mask  one flag a pixel of the compared region, row by row
 * @param count how many flags are set
 */
public record SpherePixels(boolean[] mask, int count) {

    /** How a render and an image agree on the sphere pixels. */
    public record Match(int pixels, int exact, int withinOne) {

        /** The share (0 to 1) of sphere pixels equal in the render and the image. */
        public double exactShare() {
            return pixels == 0 ? 1 : (double) exact / pixels;
        }

        /** The share (0 to 1) of sphere pixels within one level in every channel. */
        public double withinOneShare() {
            return pixels == 0 ? 1 : (double) withinOne / pixels;
        }
    }

    public SpherePixels {
        mask = mask.clone();
    }

    @Override
    public boolean[] mask() {
        return mask.clone();
    }

    /**
     * The sphere pixels of a {@code width} x {@code height} frame inside a border {@code border}
     * wide, from the flags of the whole frame; when no entry draws a sphere there, every pixel, so
     * that an image of nothing but background is still ranked on something.
     */
    static SpherePixels inside(boolean[] frame, int width, int height, int border) {
        int innerWidth = width - 2 * border, innerHeight = height - 2 * border;
        boolean[] mask = new boolean[innerWidth * innerHeight];
        int count = 0;
        for (int y = 0; y < innerHeight; y++) {
            for (int x = 0; x < innerWidth; x++) {
                boolean sphere = frame[(y + border) * width + x + border];
                mask[y * innerWidth + x] = sphere;
                count += sphere ? 1 : 0;
            }
        }
        if (count == 0) {
            Arrays.fill(mask, true);
            count = mask.length;
        }
        return new SpherePixels(mask, count);
    }

    /** How {@code a} and {@code b}, the {@link RgbPixels} of a render and an image of the mask's region, agree here. */
    Match match(int[] a, int[] b) {
        int exact = 0, withinOne = 0;
        for (int i = 0; i < a.length; i++) {
            if (mask[i]) {
                int worst = worstChannel(a[i], b[i]);
                exact += worst == 0 ? 1 : 0;
                withinOne += worst <= 1 ? 1 : 0;
            }
        }
        return new Match(count, exact, withinOne);
    }

    /** How many pixels outside the sphere pixels are not {@code background} (0xRRGGBB) in {@code b}, an image's. */
    int notBackgroundOutside(int[] b, int background) {
        int stray = 0;
        for (int i = 0; i < b.length; i++) {
            if (!mask[i] && (b[i] & 0xFFFFFF) != background) {
                stray++;
            }
        }
        return stray;
    }

    private static int worstChannel(int a, int b) {
        int worst = 0;
        for (int shift = 0; shift <= 16; shift += 8) {
            worst = Math.max(worst, Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF)));
        }
        return worst;
    }
}
