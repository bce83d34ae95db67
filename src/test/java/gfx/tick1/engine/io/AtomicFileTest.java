package gfx.tick1.engine.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A file written whole or not at all, however the JVM ends meanwhile. */
class AtomicFileTest {

    @TempDir
    Path dir;

    /**
     * A write that begins once the JVM is stopping (from a shutdown hook, as a grade's thread may still write while a
     * stop ends it) is refused as an interrupted write: no exception of another kind, and no temporary file left.
     */
    @Test
    void aWriteBegunWhileTheJvmStopsIsRefusedAsInterruptedAndLeavesNothing() throws Exception {
        Process process = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), WriteWhileStopping.class.getName(),
                dir.resolve("out.txt").toString()).redirectErrorStream(true).start();
        String said = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(process.waitFor(60, TimeUnit.SECONDS)).as("the writer ended").isTrue();

        assertThat(said).as("what the write begun while the JVM stopped did")
                .startsWith("refused: " + InterruptedIOException.class.getName());
        assertThat(dir.toFile().list()).as("what the write left").isEmpty();
    }

    /** The other JVM of the test above: it writes from a shutdown hook. */
    static final class WriteWhileStopping {
        public static void main(String[] args) {
            Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                try {
                    AtomicFile.write(Path.of(args[0]), out -> out.write('x'));
                    System.out.println("written");
                } catch (IOException | RuntimeException e) {
                    System.out.println((e instanceof IOException ? "refused: " : "failed: ") + e);
                }
            }));
            System.exit(0);
        }
    }
}
