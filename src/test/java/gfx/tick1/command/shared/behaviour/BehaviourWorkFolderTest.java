package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.EndedJvm;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.kit.StarterKit;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The behaviour check's work folder goes however tick1 ends while the methods run (Ctrl-C, SIGTERM). */
class BehaviourWorkFolderTest {

    @TempDir
    Path dir;

    @Test
    void aCheckUnderWayWhenTheJvmEndsLeavesNoWorkFolder() throws IOException, InterruptedException {
        EndedJvm ended = EndedJvm.of(EndDuringCheck.class, Files.createDirectory(dir.resolve("tmp")));

        assertThat(ended.said()).as("whether the JVM ended while the check's folder was there")
                .startsWith("ended during");
        assertThat(ended.left()).as("what the check left in the temporary folder").isEmpty();
    }

    /** The other JVM of the test above: it ends once the check's work folder holds the run's output folder. */
    static final class EndDuringCheck {
        public static void main(String[] args) throws IOException {
            Thread check = new Thread(() -> {
                try {
                    BehaviourCheck.call(Sandbox.unconfined(), StarterKit.source("Sphere"),
                            StarterKit.source("Renderer"), null);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "check");
            check.setDaemon(true);
            check.start();
            EndedJvm.endOnceMade("tick1-behaviour-", folder -> Files.isDirectory(folder.resolve("output")), 30);
        }
    }
}
