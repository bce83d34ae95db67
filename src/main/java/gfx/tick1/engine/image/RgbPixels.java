package gfx.tick1.engine.image;

import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;

/**
 * An image's colours as packed 0xRRGGBB ints, row by row from the top, alpha left out: what
 * {@code getRGB} gives with its top byte cleared. Comparing a render with an image reads the image
 * once per catalogue entry, and {@code getRGB} converts every pixel through the image's colour model
 * one call at a time; the images tick1 meets (its own renders, which are TYPE_INT_RGB, and PNGs as
 * ImageIO reads them, TYPE_3BYTE_BGR or TYPE_4BYTE_ABGR) are copied from their rasters instead.
 * When their colours are sRGB's and unpremultiplied, the raster's samples are {@code getRGB}'s
 * channels; any other image goes through {@code getRGB}.
 */
public final class RgbPixels {

    private RgbPixels() {
    }

    /** The colours of {@code image}, {@code width * height} of them. */
    public static int[] of(BufferedImage image) {
        int width = image.getWidth(), height = image.getHeight();
        int[] rgb = new int[width * height];
        // The type alone does not say sRGB or unpremultiplied: an image of linear RGB bytes is TYPE_3BYTE_BGR too,
        // and coerceData(true) premultiplies an INT_ARGB image's colours without changing its type. getRGB takes
        // the colour space as sRGB only when it is that instance, and a subclass may answer getRGB itself.
        ColorModel model = image.getColorModel();
        boolean plainSrgb = model.getColorSpace() == ColorSpace.getInstance(ColorSpace.CS_sRGB)
                && !model.isAlphaPremultiplied() && image.getClass() == BufferedImage.class;
        int type = plainSrgb ? image.getType() : BufferedImage.TYPE_CUSTOM;
        switch (type) {
            // A pixel's data element is its packed int (alpha in the top byte for INT_ARGB).
            case BufferedImage.TYPE_INT_RGB, BufferedImage.TYPE_INT_ARGB ->
                    image.getRaster().getDataElements(0, 0, width, height, rgb);
            // A pixel's data elements are its bands in the colour model's order: red, green, blue (then alpha).
            case BufferedImage.TYPE_3BYTE_BGR -> fromBytes(image, rgb, 3);
            case BufferedImage.TYPE_4BYTE_ABGR -> fromBytes(image, rgb, 4);
            default -> image.getRGB(0, 0, width, height, rgb, 0, width);
        }
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }

    private static void fromBytes(BufferedImage image, int[] rgb, int bands) {
        int width = image.getWidth();
        byte[] row = new byte[width * bands];
        for (int y = 0; y < image.getHeight(); y++) {
            image.getRaster().getDataElements(0, y, width, 1, row);
            for (int x = 0, i = 0; x < width; x++, i += bands) {
                rgb[y * width + x] = (row[i] & 0xFF) << 16 | (row[i + 1] & 0xFF) << 8 | row[i + 2] & 0xFF;
            }
        }
    }
}
