package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.CliRun;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The trial mount that tells whether each run's output folder can be a file system of its own: it leaves
 * nothing, however tick1 ends meanwhile. {@code tick1 diff} makes its sandbox while it parses the files, so it
 * may end (a file of another class, our own files) while the trial is under way. (Mounting needs root.)
 */
class TrialMountTest {

    @TempDir
    Path dir;

    @Test
    void aTrialUnderWayWhenTheJvmEndsLeavesNoFolderAndNoMount() throws IOException, InterruptedException {
        Path temporary = Files.createDirectory(dir.resolve("tmp"));
        assumeThat(OutputDisk.canMount(Files.createDirectory(dir.resolve("scratch"))))
                .as("a tmpfs can be mounted here (as root)").isTrue();
        List<String> command = CliRun.java();
        command.addAll(List.of("-Djava.io.tmpdir=" + temporary, "-cp", System.getProperty("java.class.path"),
                EndDuringTrial.class.getName()));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String said = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(process.waitFor(60, TimeUnit.SECONDS)).as("the JVM ended").isTrue();

        assertThat(said).as("whether the JVM ended while the trial's folder was there").startsWith("ended during");
        assertThat(OutputDisk.mountPoints()).as("the file systems mounted in the temporary folder")
                .noneMatch(point -> point.startsWith(temporary.toString()));
        try (Stream<Path> left = Files.list(temporary)) {
            assertThat(left.toList()).as("what the trial left in the temporary folder").isEmpty();
        }
    }

    /** The other JVM of the test above: it ends as soon as the trial's folder is there. */
    static final class EndDuringTrial {
        public static void main(String[] args) throws IOException {
            Path temporary = Path.of(System.getProperty("java.io.tmpdir"));
            Thread trial = new Thread(Host::canMountOutputDisks, "trial");
            trial.setDaemon(true);
            trial.start();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (System.nanoTime() < end) {
                try (Stream<Path> names = Files.list(temporary)) {
                    if (names.anyMatch(name -> name.getFileName().toString().startsWith("tick1-mount-"))) {
                        System.out.println("ended during the trial");
                        System.exit(0);
                    }
                }
            }
            System.out.println("the trial's folder was never seen");
        }
    }
}
