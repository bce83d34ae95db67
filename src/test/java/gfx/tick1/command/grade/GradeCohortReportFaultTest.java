package gfx.tick1.command.grade;

import static gfx.tick1.command.grade.GradeCohortTest.files;
import static gfx.tick1.command.grade.GradeCohortTest.gradeArguments;
import static gfx.tick1.command.grade.GradeCohortTest.moodleZip;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.CliRun;
import gfx.tick1.TestTmpfs;
import gfx.tick1.command.grade.GradeCohortTest.Student;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * A cohort whose report folder cannot take its results: full, or read-only. The report folder is the
 * user's, not tick1's: it is named with the cause in one line, the exit status is the report's, never an
 * internal error's, and no student vanishes from the counts. The state folder is a tmpfs the test mounts
 * (as root, where mounting is allowed; skipped elsewhere), so that the rest of the report can be written.
 */
@ExtendWith(SandboxNeeded.class)
class GradeCohortReportFaultTest {

    @TempDir
    static Path dir;

    private static final List<Path> MOUNTED = new ArrayList<>();
    private static CliRun full;
    private static CliRun readOnly;

    @AfterAll
    static void unmount() throws Exception {
        for (Path folder : MOUNTED) {
            TestTmpfs.unmount(folder);
        }
    }

    /** The report folder {@code name}, its state folder a tmpfs mounted with {@code options}. */
    private static Path reportWithState(String name, String options) throws IOException, InterruptedException {
        Path state = Files.createDirectories(dir.resolve(name).resolve(CohortCommand.STATE_FOLDER));
        TestTmpfs.mount(state, options);
        MOUNTED.add(state);
        return state.getParent();
    }

    /** Twins (the same wrong files), graded once, with a state folder with room for no file. */
    private static synchronized CliRun full() throws IOException, InterruptedException {
        if (full == null) {
            StudentSolution wrong = StudentSolution.correct().editRenderer("return image;",
                    "image.setRGB(0, 0, 0xFFFFFF); return image;");
            Path zip = moodleZip(dir.resolve("twins.zip"), List.of(new Student("Carl Twin", 103, files(wrong), false),
                    new Student("Dora Twin", 104, files(wrong), false)));
            full = CliRun.of(gradeArguments(zip, reportWithState("full", "size=8m,nr_inodes=3"), "--jobs", "1"));
        }
        return full;
    }

    /** One correct student, with a read-only state folder. */
    private static synchronized CliRun readOnly() throws IOException, InterruptedException {
        if (readOnly == null) {
            Path zip = moodleZip(dir.resolve("one.zip"), List.of(new Student("Ann Smith", 101,
                    files(StudentSolution.correct()), true)));
            Path report = reportWithState("read-only", "size=8m");
            Process remount = new ProcessBuilder("/bin/mount", "-o", "remount,ro", report.resolve(
                    CohortCommand.STATE_FOLDER).toString()).redirectErrorStream(true).start();
            assumeThat(remount.waitFor()).as("the tmpfs can be made read-only").isZero();
            readOnly = CliRun.of(gradeArguments(zip, report, "--jobs", "1"));
        }
        return readOnly;
    }

    @Test
    void aTwinOfAStudentWhoseImagesCouldNotBeStoredIsCountedAndHasARowAsTheyDo() throws Exception {
        CliRun run = full();

        assertThat(run.out()).as(run.transcript()).contains("0 passed, 0 failed, 2 not graded");
        assertThat(GradeCohortTest.rows(dir.resolve("full"))).as("grades.csv's rows").containsKeys(
                "Participant 103", "Participant 104");
    }

    @Test
    void aFullReportDisksLineNamesTheReportFolderAndItsCauseNotAFolderOfTick1sOwn() throws Exception {
        CliRun run = full();

        assertThat(run.err()).as(run.transcript()).doesNotContain(".writing-");
        assertThat(run.err().lines().filter(line -> line.contains("No space left on device")))
                .as(run.transcript()).singleElement().asString().contains(dir.resolve("full").toString());
    }

    @Test
    void aReportFolderThatTakesNoResultIsOneLineNamingItAndItsCauseWithTheReportsExitStatus() throws Exception {
        CliRun run = readOnly();

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_CANNOT_WRITE);
        assertThat(run.err()).as(run.transcript()).doesNotContain("an error in tick1", "internal error");
        assertThat(run.err().lines().filter(line -> line.contains("not graded") || line.contains("cannot")))
                .as(run.transcript()).singleElement().asString()
                .contains(dir.resolve("read-only").toString(), "Read-only file system");
    }
}
