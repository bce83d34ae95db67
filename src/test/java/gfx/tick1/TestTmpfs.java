package gfx.tick1;

import static org.assertj.core.api.Assumptions.assumeThat;

import java.io.IOException;
import java.nio.file.Path;

/** A tmpfs a test mounts on a folder of its own, to give the grader a small or full disk; only root can. */
public final class TestTmpfs {

    private TestTmpfs() {
    }

    /** Mounts a tmpfs with {@code options} (size, inodes, mode) on {@code folder}; skips the test where it cannot. */
    public static void mount(Path folder, String options) throws IOException, InterruptedException {
        Process mount = new ProcessBuilder("/bin/mount", "-t", "tmpfs", "-o", options, "tick1-test", folder.toString())
                .redirectErrorStream(true).start();
        assumeThat(mount.waitFor()).as("a tmpfs can be mounted here (as root)").isZero();
    }

    /**
     * Unmounts the tmpfs on {@code folder} lazily: a process another test class starts meanwhile can hold the mount
     * a moment ("target is busy"), and the test's folder could then not be deleted.
     */
    public static void unmount(Path folder) throws IOException, InterruptedException {
        new ProcessBuilder("/bin/umount", "--lazy", folder.toString()).inheritIO().start().waitFor();
    }
}
