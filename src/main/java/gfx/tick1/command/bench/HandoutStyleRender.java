package gfx.tick1.command.bench;

import gfx.tick1.engine.render.Camera;
import gfx.tick1.engine.render.Renderer;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * The benchmark's yardstick for start-up: what the course's own program does, as a plain
 * {@code java} run. One thread, one {@code castRay} and one {@code trace} per pixel through the
 * readable Renderer, then ImageIO's PNG writer; no command-line library.
 * Usage: {@code java -cp ... gfx.tick1.command.bench.HandoutStyleRender SCENE.xml OUT.png}.
 */
public final class HandoutStyleRender extends Renderer {

    private final int width, height;

    private HandoutStyleRender(int width, int height) {
        super(width, height);
        this.width = width;
        this.height = height;
    }

    public static void main(String[] args) throws IOException {
        Scene scene = new SceneLoader(Path.of(args[0]), false).getScene();
        BufferedImage image = new HandoutStyleRender(640, 480).renderOnOneThread(scene);
        ImageIO.write(image, "png", new File(args[1]));
    }

    private BufferedImage renderOnOneThread(Scene scene) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Camera camera = new Camera(width, height);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, trace(scene, camera.castRay(x, y)).toRGB());
            }
        }
        return image;
    }
}
