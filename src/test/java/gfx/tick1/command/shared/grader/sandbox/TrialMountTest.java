package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.EndedJvm;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
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

        EndedJvm ended = EndedJvm.of(EndDuringTrial.class, temporary);

        assertThat(ended.said()).as("whether the JVM ended while the trial's folder was there")
                .startsWith("ended during");
        assertThat(OutputDisk.mountPoints()).as("the file systems mounted in the temporary folder")
                .noneMatch(point -> point.startsWith(temporary.toString()));
        assertThat(ended.left()).as("what the trial left in the temporary folder").isEmpty();
    }

    /**
     * The other JVM of the test above: it ends as soon as a trial's folder is there. A trial lasts milliseconds, so
     * one follows another until then.
     */
    static final class EndDuringTrial {
        public static void main(String[] args) throws IOException {
            Thread trial = new Thread(() -> {
                while (true) {
                    Host.canMountOutputDisks();
                }
            }, "trials");
            trial.setDaemon(true);
            trial.start();
            EndedJvm.endOnceMade("tick1-mount-", folder -> true, 20);
        }
    }
}
