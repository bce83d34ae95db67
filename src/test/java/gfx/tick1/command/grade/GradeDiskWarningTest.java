package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.SandboxProperties;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Where the sandbox cannot give each run an output folder of its own that the kernel holds
 * (grading as a normal user, or where no tmpfs can be mounted), the grade says so in one warning
 * line, and grades. The system property tick1.grade.outputDisks=host makes such a sandbox on a
 * machine that could mount one.
 */
@SandboxProperties.Written
class GradeDiskWarningTest {

    private static final String PROPERTY = "tick1.grade.outputDisks";

    @TempDir
    Path dir;

    @BeforeEach
    void noOutputDisks() throws InterruptedException {
        System.setProperty(PROPERTY, "host");
        try {
            Sandbox.confined();
        } catch (Sandbox.Unavailable e) {
            assumeThat(e.getMessage()).as("bubblewrap is needed for the sandbox's warnings").isNull();
        }
    }

    @AfterEach
    void outputDisksAsTheMachineAllows() {
        System.clearProperty(PROPERTY);
    }

    @Test
    void withoutOutputDisksTheGradeSaysSoInOneWarningLineAndGrades() throws Exception {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        String warning = Sandbox.confined().diskNotEnforced();
        assertThat(warning).as("the sandbox's word that the output folder is on the host's disk").isNotNull();

        CliRun run = CliRun.of("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--report", dir.resolve("report").toString(), "--width", "160", "--height", "120");

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.err().lines()).as("what the grade printed on stderr")
                .containsOnlyOnce("tick1 grade: warning: " + warning);
    }
}
