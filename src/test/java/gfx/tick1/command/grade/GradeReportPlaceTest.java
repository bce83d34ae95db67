package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * A report folder that is the download itself, or inside a student's folder of it, would be read
 * as students' files by the next grade: it is refused in one line, before anything is written. A cohort
 * is graded only in the sandbox, whose absence would be the one line instead.
 */
@ExtendWith(SandboxNeeded.class)
class GradeReportPlaceTest {

    @TempDir
    Path dir;

    private Path download() throws IOException {
        Path student = Files.createDirectories(dir.resolve("download")
                .resolve("Ada Lovelace_1001_assignsubmission_file"));
        Files.writeString(student.resolve("Sphere.java"), "class Sphere {}");
        Files.writeString(student.resolve("Renderer.java"), "class Renderer {}");
        return student.getParent();
    }

    @Test
    void aReportFolderThatIsTheDownloadIsRefusedInOneLine() throws IOException {
        Path download = download();

        CliRun run = CliRun.of("grade", "--submissions", download.toString(), "--report", download.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines().filter(line -> line.contains("--report"))).as(run.transcript()).hasSize(1);
        assertThat(download.resolve("grades.csv")).as("a report in the download").doesNotExist();
    }

    @Test
    void aReportFolderInsideAStudentsFolderIsRefusedInOneLine() throws IOException {
        Path download = download();
        Path report = download.resolve("Ada Lovelace_1001_assignsubmission_file").resolve("report");

        CliRun run = CliRun.of("grade", "--submissions", download.toString(), "--report", report.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines().filter(line -> line.contains("--report"))).as(run.transcript()).hasSize(1);
        assertThat(report).as("the report folder").doesNotExist();
    }
}
