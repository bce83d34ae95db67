package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * Where the sandbox cannot give each run an output folder of its own that the kernel holds
 * (grading as a normal user, or where no tmpfs can be mounted), the grade says so in one warning
 * line, after its own answer, and grades; as it does of the sandbox's other weaknesses (no control
 * group). The system property tick1.grade.outputDisks=host makes such a sandbox on a machine that
 * could mount one: it is given to a tick1 in a JVM of its own, so that the classes grading in the
 * tests' JVM beside this one keep their output disks.
 */
@ExtendWith(SandboxNeeded.class)
class GradeDiskWarningTest {

    /** The start of the warning, whichever of the two reasons the machine gives. */
    private static final String WARNING = "tick1 grade: warning: ";
    private static final String HOST_DISK = "the output folder of each run is on the host's disk";

    @TempDir
    Path dir;

    /** {@code tick1 args...} in a JVM of its own whose sandbox mounts no output disks. */
    private CliRun withoutOutputDisks(String... args) throws IOException, InterruptedException {
        return CliRun.inJvm(dir, List.of("-Dtick1.grade.outputDisks=host"), args);
    }

    @Test
    void withoutOutputDisksTheGradeSaysSoInOneWarningLineAndGrades() throws Exception {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));

        CliRun run = withoutOutputDisks("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--report", dir.resolve("report").toString(), "--width", "160", "--height", "120");

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.err().lines().filter(line -> line.contains(HOST_DISK)))
                .as("what the grade printed on stderr: %s", run.transcript()).singleElement().asString()
                .startsWith(WARNING);
    }

    /** The grade's own words come first (here, that a failure's images could not be written); the warning last. */
    @Test
    void theWarningComesAfterTheGradesOwnAnswer() throws Exception {
        Path[] files = StudentSolution.correct().editRenderer("k_d * Math.max(0, NdotL)", "k_d * NdotL")
                .writeTo(dir.resolve("student"));
        Files.writeString(dir.resolve("report"), "a file where the report folder should go");

        CliRun run = withoutOutputDisks("grade", "--sphere", files[0].toString(), "--renderer",
                files[1].toString(), "--report", dir.resolve("report").toString(), "--width", "160", "--height", "120");

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_CANNOT_WRITE);
        List<String> err = run.err().lines().toList();
        assertThat(err).as("what the grade printed on stderr").hasSizeGreaterThan(1)
                .first().asString().contains("exists and is not a folder");
        assertThat(err.get(err.size() - 1)).as("the last line it printed on stderr").startsWith(WARNING)
                .contains(HOST_DISK);
    }

    /** Nothing was graded, so there is nothing for a warning to qualify: the error is the one line. */
    @Test
    void aOneLineErrorIsAllThatIsPrinted() throws Exception {
        CliRun run = withoutOutputDisks("grade", "--sphere", dir.resolve("Sphere.java").toString(), "--renderer",
                dir.resolve("Renderer.java").toString(), "--report", dir.resolve("report").toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).as("what the grade printed on stderr").hasSize(1)
                .allMatch(line -> line.startsWith("tick1 grade: ") && !line.startsWith(WARNING));
    }
}
