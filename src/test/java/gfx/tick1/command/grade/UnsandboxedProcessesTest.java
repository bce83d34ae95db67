package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code grade --no-sandbox}: the Java process that runs the student's code stops the processes the code started
 * when it ends, and ends itself when tick1 is gone (killed with SIGKILL, which no clean-up of tick1's survives).
 */
@Order(19)   // one of the longest classes: it starts early (junit-platform.properties)
class UnsandboxedProcessesTest {

    /** The render's own sleep: far longer than any wait of these tests. */
    private static final String SLEEP_SECONDS = "313.25";

    @TempDir
    Path dir;

    @Test
    void aProcessTheCodeStartedAndLeftRunningIsStoppedWhenTheGradeEnds() throws Exception {
        Path[] files = StudentSolution.correct().editRenderer("return image;", "try { new ProcessBuilder("
                + "\"sleep\", \"" + SLEEP_SECONDS + "\").start(); } catch (java.io.IOException e) { } return image;")
                .writeTo(dir.resolve("student"));
        try {
            CliRun run = CliRun.inJvm(dir, List.of(), "grade", "--sphere", files[0].toString(), "--renderer",
                    files[1].toString(), "--no-sandbox", "--width", "16", "--height", "12");

            assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
            assertThat(sleeps()).as("the processes the student's code started, once the grade has ended").isEmpty();
        } finally {
            sleeps().forEach(ProcessHandle::destroyForcibly);
        }
    }

    @Test
    void theJavaThatRunsTheCodeEndsWhenTickOneIsKilled() throws Exception {
        Path[] files = StudentSolution.correct().editRenderer("return image;", "try { Thread.sleep((long) ("
                + SLEEP_SECONDS + " * 1000)); } catch (InterruptedException e) { } return image;")
                .writeTo(dir.resolve("student"));
        Process grade = GradeCohortTest.gradeInAJvmOfItsOwn(dir, "grade", "--sphere", files[0].toString(),
                "--renderer", files[1].toString(), "--no-sandbox", "--width", "16", "--height", "12",
                "--time-limit", "600");
        List<ProcessHandle> harness = List.of();
        try {
            for (int i = 0; i < 1200 && grade.isAlive() && harness.isEmpty(); i++) {
                Thread.sleep(100);
                harness = grade.descendants().filter(p -> p.info().commandLine().orElse("")
                        .contains("StudentHarness render")).toList();
            }
            assertThat(harness).as("the student's code runs: " + Files.readString(dir.resolve("grade.log")))
                    .isNotEmpty();

            grade.destroyForcibly().waitFor();

            for (ProcessHandle process : harness) {
                assertThat(process.onExit().completeOnTimeout(null, 30, TimeUnit.SECONDS).get())
                        .as("the Java that runs the student's code, 30 s after tick1 was killed: " + process.pid() + " "
                                + process.info() + " " + state(process)).isNotNull();
            }
        } finally {
            harness.forEach(ProcessHandle::destroyForcibly);
            grade.destroyForcibly();
        }
    }

    /** What Linux says of {@code process}, for the message of a failure. */
    private static String state(ProcessHandle process) {
        try {
            return Files.readAllLines(Path.of("/proc", Long.toString(process.pid()), "status")).toString();
        } catch (java.io.IOException e) {
            return e.toString();
        }
    }

    /** The sleeps that the student's code started, wherever they are now. */
    private static List<ProcessHandle> sleeps() {
        return ProcessHandle.allProcesses().filter(p -> p.info().arguments().map(List::of)
                .filter(args -> args.contains(SLEEP_SECONDS)).isPresent()).toList();
    }
}
