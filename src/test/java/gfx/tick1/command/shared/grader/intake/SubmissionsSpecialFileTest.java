package gfx.tick1.command.shared.grader.intake;

import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.command.shared.grader.model.CohortInputException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A download given as something that is there but is neither a file nor a folder is named for what it is. */
class SubmissionsSpecialFileTest {

    @TempDir
    Path dir;

    @Test
    void aNamedPipeIsCalledANamedPipe() throws Exception {
        Path fifo = dir.resolve("download");
        boolean made;
        try {
            Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
            made = mkfifo.waitFor(30, TimeUnit.SECONDS) && mkfifo.exitValue() == 0;
        } catch (java.io.IOException e) {
            made = false;
        }
        assumeThat(made).as("mkfifo can make a named pipe here").isTrue();

        assertThatThrownBy(() -> Submissions.read(fifo)).isInstanceOf(CohortInputException.class)
                .hasMessageContaining("a named pipe").hasMessageNotContaining("no such");
    }

    @Test
    void aDeviceIsCalledADevice() {
        Path device = Path.of("/dev/null");
        assumeThat(Files.exists(device)).as("this system has /dev/null").isTrue();

        assertThatThrownBy(() -> Submissions.read(device)).isInstanceOf(CohortInputException.class)
                .hasMessageContaining("a device").hasMessageNotContaining("no such");
    }
}
