package gfx.tick1.command.shared.diagnosis;

import gfx.tick1.engine.render.Camera;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.Scene;
import java.awt.image.BufferedImage;

/**
 * The correct colour of single pixels of a scene, traced as the reference renderer traces them:
 * enough of them, spread over the frame, rule a scene out without rendering it whole.
 */
final class PixelSampler extends ReferenceRenderer {

    /** About how many pixels {@link #mayBe} traces: a grid over the frame. */
    private static final int SAMPLES = 5000;

    private final Camera camera;
    private final int width, height;

    PixelSampler(int width, int height) {
        super(width, height);
        this.camera = new Camera(width, height);
        this.width = width;
        this.height = height;
    }

    /**
     * Whether {@code image} may be the correct render of {@code scene}: its pixels on a grid
     * over the frame inside {@code border} are the correct colours. False rules the scene out; true
     * is to be confirmed on every pixel.
     */
    boolean mayBe(BufferedImage image, Scene scene, int border) {
        int step = (int) Math.max(1, Math.sqrt((double) width * height / SAMPLES));
        for (int y = border; y < height - border; y += step) {
            for (int x = border; x < width - border; x += step) {
                if ((trace(scene, camera.castRay(x, y)).toRGB() & 0xFFFFFF) != (image.getRGB(x, y) & 0xFFFFFF)) {
                    return false;
                }
            }
        }
        return true;
    }
}
