package gfx.tick1;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;

/**
 * Uses more memory than any one process may, by spreading it over several: each process keeps
 * 300 MB (tail holds a line of 300 MB of zero bytes, which has no line break), well within its
 * own address-space limit, and together they hold far more than one grade's memory.
 */
public class Renderer {

    public Renderer(int width, int height) {
    }

    public BufferedImage render(Scene scene) {
        List<Process> hogs = new ArrayList<>();
        StringBuilder said = new StringBuilder();
        try {
            for (int i = 0; i < 4; i++) {
                hogs.add(new ProcessBuilder("/bin/sh", "-c", "head -c 300000000 /dev/zero | tail > /dev/null")
                        .start());
            }
            for (Process hog : hogs) {
                said.append(hog.waitFor()).append(' ');
            }
        } catch (Exception e) {
            said.append(e);
        }
        throw new IllegalStateException("the processes ended with " + said);
    }
}
