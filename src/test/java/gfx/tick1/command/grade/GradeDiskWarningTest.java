package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.SandboxProperties;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Where the sandbox cannot give each run an output folder of its own that the kernel holds
 * (grading as a normal user, or where no tmpfs can be mounted), the grade says so in one warning
 * line, after its own answer, and grades; as it does of the sandbox's other weaknesses (no control
 * group). The system property tick1.grade.outputDisks=host makes such a sandbox on a machine that
 * could mount one.
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
        String warning = Sandbox.confined().enforcement().diskNotEnforced();
        assertThat(warning).as("the sandbox's word that the output folder is on the host's disk").isNotNull();

        CliRun run = CliRun.of("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--report", dir.resolve("report").toString(), "--width", "160", "--height", "120");

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.err().lines()).as("what the grade printed on stderr")
                .containsOnlyOnce("tick1 grade: warning: " + warning);
    }

    /** The grade's own words come first (here, that a failure's images could not be written); the warning last. */
    @Test
    void theWarningComesAfterTheGradesOwnAnswer() throws Exception {
        Path[] files = StudentSolution.correct().editRenderer("k_d * Math.max(0, NdotL)", "k_d * NdotL")
                .writeTo(dir.resolve("student"));
        Files.writeString(dir.resolve("report"), "a file where the report folder should go");

        CliRun run = CliRun.of("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--report", dir.resolve("report").toString(), "--width", "160", "--height", "120");

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_CANNOT_WRITE);
        assertThat(run.err().lines().toList()).as("what the grade printed on stderr").hasSizeGreaterThan(1)
                .endsWith("tick1 grade: warning: " + Sandbox.confined().enforcement().diskNotEnforced())
                .first().asString().contains("exists and is not a folder");
    }

    /** Nothing was graded, so there is nothing for a warning to qualify: the error is the one line. */
    @Test
    void aOneLineErrorIsAllThatIsPrinted() {
        CliRun run = CliRun.of("grade", "--sphere", dir.resolve("Sphere.java").toString(), "--renderer",
                dir.resolve("Renderer.java").toString(), "--report", dir.resolve("report").toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).as("what the grade printed on stderr").hasSize(1)
                .allMatch(line -> line.startsWith("tick1 grade: ") && !line.startsWith("tick1 grade: warning:"));
    }
}
