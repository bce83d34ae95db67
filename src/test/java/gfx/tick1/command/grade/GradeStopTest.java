package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * One student's grade stopped while their code runs: it says once that it was stopped, prints no
 * verdict after that (the stop, not the code, ended the run), and ends with the status its help
 * gives a stop.
 */
@ExtendWith(SandboxNeeded.class)
class GradeStopTest {

    @TempDir
    Path dir;

    @Test
    void aGradeStoppedWithSigtermSaysSoOnceAsItsLastLineAndEndsWithTheStatusOfAStop() throws Exception {
        Path[] files = StudentSolution.correct().editRenderer("return image;",
                "try { Thread.sleep(30_000); } catch (InterruptedException e) { } return image;")
                .writeTo(dir.resolve("student"));
        Process grade = GradeCohortTest.gradeInAJvmOfItsOwn(dir, "grade", "--sphere", files[0].toString(),
                "--renderer", files[1].toString(), "--report", dir.resolve("report").toString(),
                "--width", "160", "--height", "120", "--time-limit", "60");
        awaitTheStudentsCode(grade);

        new ProcessBuilder("/bin/kill", "-TERM", Long.toString(grade.pid())).start().waitFor();

        assertThat(grade.waitFor(60, TimeUnit.SECONDS)).as("the grade ended").isTrue();
        List<String> said = Files.readAllLines(dir.resolve("grade.log"));
        String stopped = "tick1 grade: the grade was stopped (Ctrl-C or SIGTERM); no verdict";
        assertThat(said).as("what the stopped grade said").filteredOn(stopped::equals).hasSize(1);
        assertThat(said).as("what the stopped grade said").last().isEqualTo(stopped);
        assertThat(grade.exitValue()).as("the stopped grade's status, as its help says: " + said)
                .isEqualTo(GradeCommand.EXIT_STOPPED);
    }

    /**
     * A grade stopped with SIGTERM before the student's code runs (while the sandbox is being made: its bubblewrap
     * here waits before it runs) says so in the one stop line, as a later stop does.
     */
    @Test
    void aGradeStoppedBeforeItsSandboxIsMadeSaysSoAsItsLastLine() throws Exception {
        SlowBubblewrap bubblewrap = SlowBubblewrap.in(dir);
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        Process grade = GradeCohortTest.gradeInAJvmOfItsOwn(dir, List.of(bubblewrap.jvmOption()),
                "grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(), "--width", "16",
                "--height", "12");
        bubblewrap.awaitBegun(grade);
        List<ProcessHandle> waiting = grade.descendants().toList();

        new ProcessBuilder("/bin/kill", "-TERM", Long.toString(grade.pid())).start().waitFor();
        assertThat(grade.waitFor(60, TimeUnit.SECONDS)).as("the grade ended").isTrue();
        waiting.forEach(ProcessHandle::destroy);

        List<String> said = Files.readAllLines(dir.resolve("grade.log"));
        assertThat(said).as("what the stopped grade said").last()
                .isEqualTo("tick1 grade: the grade was stopped (Ctrl-C or SIGTERM); no verdict");
    }

    /** Waits (at most two minutes) for the student's render to run. */
    private void awaitTheStudentsCode(Process grade) throws IOException, InterruptedException {
        for (int i = 0; i < 1200 && grade.isAlive() && grade.descendants()
                .noneMatch(p -> p.info().commandLine().orElse("").contains("StudentHarness render")); i++) {
            Thread.sleep(100);
        }
        assertThat(grade.isAlive()).as("the grade runs: " + Files.readString(dir.resolve("grade.log"))).isTrue();
    }
}
