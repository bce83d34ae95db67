package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * A file that {@code tick1 grade} reads whole, given as a device that never ends ({@code /dev/zero}): it is read
 * no further than any real file of its kind goes, and refused in one line that names it, with exit status 2.
 */
class GradeEndlessFileTest {

    private static final Path ZERO = Path.of("/dev/zero");

    @TempDir
    Path dir;

    @BeforeEach
    void needsDevZero() {
        assumeTrue(Files.isReadable(ZERO), "needs /dev/zero");
    }

    @Test
    void aSphereThatNeverEndsIsRefusedInOneLine() throws Exception {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));

        CliRun run = CliRun.inJvm(dir, List.of("-Xmx256m"), "grade", "--sphere", ZERO.toString(), "--renderer",
                files[1].toString(), "--no-sandbox", "--width", "16", "--height", "12");

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).as(run.transcript()).contains("tick1 grade: /dev/zero: larger than 1 MiB, far "
                + "more than any Sphere.java or Renderer.java").noneMatch(line -> line.contains("out of memory"));
    }

    /** A cohort is graded only in the sandbox, whose absence would be the one line instead. */
    @Test
    @ExtendWith(SandboxNeeded.class)
    void aWorksheetThatNeverEndsIsRefusedInOneLineBeforeAnythingIsGraded() throws Exception {
        Path download = Files.createDirectory(dir.resolve("download"));

        CliRun run = CliRun.inJvm(dir, List.of("-Xmx256m"), "grade", "--submissions", download.toString(),
                "--worksheet", ZERO.toString(), "--report", dir.resolve("report").toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err()).as(run.transcript()).startsWith("tick1 grade: /dev/zero: larger than ");
        assertThat(run.err().lines()).as(run.transcript()).hasSize(1);
    }
}
