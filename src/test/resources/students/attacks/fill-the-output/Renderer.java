package gfx.tick1;

import java.awt.image.BufferedImage;
import java.io.FileOutputStream;
import java.io.OutputStream;

/**
 * Fills the one folder on the host's disk it may write, /output, with files of 32 MiB (under the
 * limit on one file's size), as many as it can, and says how many it wrote.
 */
public class Renderer {

    public Renderer(int width, int height) {
    }

    public BufferedImage render(Scene scene) {
        byte[] mib = new byte[1 << 20];
        int files = 0;
        try {
            for (; files < 64; files++) {
                try (OutputStream out = new FileOutputStream("/output/fill-" + files)) {
                    for (int i = 0; i < 32; i++) {
                        out.write(mib);
                    }
                }
            }
        } catch (Exception e) {
            throw new IllegalStateException("wrote " + files + " files: " + e);
        }
        throw new IllegalStateException("wrote " + files + " files of 32 MiB");
    }
}
