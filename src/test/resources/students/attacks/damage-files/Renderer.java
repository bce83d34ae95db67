package gfx.tick1;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

/** Deletes and changes files outside its folder, the grader's own installation included. */
public class Renderer {

    public Renderer(int width, int height) {
    }

    public BufferedImage render(Scene scene) {
        StringBuilder done = new StringBuilder();
        try {
            Files.writeString(Path.of("/tmp/tick1-attack-victim.txt"), "#!/bin/sh\necho owned\n");
            done.append("changed the victim; ");
        } catch (Exception e) {
            done.append(e).append("; ");
        }
        try {
            Files.delete(Path.of("/tmp/tick1-attack-victim.txt"));
            done.append("deleted the victim; ");
        } catch (Exception e) {
            done.append(e).append("; ");
        }
        try {
            Files.writeString(Path.of("/usr/tick1-attack-leak.txt"), "planted");
            done.append("wrote into /usr; ");
        } catch (Exception e) {
            done.append(e).append("; ");
        }
        try {
            Files.writeString(Path.of(System.getProperty("java.home"), "tick1-attack-leak.txt"), "planted");
            done.append("wrote into java.home; ");
        } catch (Exception e) {
            done.append(e).append("; ");
        }
        throw new IllegalStateException(done.toString());
    }
}
