package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What a tick1 run killed with SIGKILL leaves in the temporary folder carries its process id, whichever command
 * made it, and the next grade of one student removes it before it starts, as a cohort's grade does.
 */
class KilledRunsLeftoversTest {

    @TempDir
    Path dir;

    @Test
    void aSingleGradeRemovesTheWorkFolderOfARunWhoseProcessIsGone() throws Exception {
        Path temporary = Files.createDirectory(dir.resolve("tmp"));
        Process done = new ProcessBuilder("/bin/true").start();
        assertThat(done.waitFor(30, TimeUnit.SECONDS)).isTrue();
        Path left = Files.createDirectory(temporary.resolve("tick1-grade-" + done.pid() + "-1"));
        Files.writeString(left.resolve("hidden.xml"), "<scene/>");
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));

        CliRun run = CliRun.inJvm(dir, List.of("-Djava.io.tmpdir=" + temporary), "grade", "--sphere",
                files[0].toString(), "--renderer", files[1].toString(), "--no-sandbox", "--width", "16", "--height",
                "12");

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(left).as("the work folder of a run whose process is gone").doesNotExist();
    }

    @Test
    void theBehaviourChecksWorkFolderOfAKilledDiffIsRemovedByTheNextGrade() throws Exception {
        Path[] files = StudentSolution.correct().editSphere("public RaycastHit intersectionWith(Ray ray) {",
                "public RaycastHit intersectionWith(Ray ray) { try { Thread.sleep(60_000); } "
                        + "catch (InterruptedException e) { }").writeTo(dir.resolve("student"));
        Process diff = GradeCohortTest.gradeInAJvmOfItsOwn(dir, "diff", "--no-sandbox", files[0].toString());
        Path temporary = dir.resolve("tmp");
        try {
            for (int i = 0; i < 1200 && diff.isAlive() && diff.descendants().noneMatch(p -> p.info().commandLine()
                    .orElse("").contains("StudentHarness")); i++) {
                Thread.sleep(100);
            }
            assertThat(diff.isAlive()).as("the diff runs: " + Files.readString(dir.resolve("grade.log"))).isTrue();
            List<ProcessHandle> harness = diff.descendants().toList();
            diff.destroyForcibly().waitFor();
            harness.forEach(ProcessHandle::destroyForcibly);
        } finally {
            diff.descendants().forEach(ProcessHandle::destroyForcibly);
            diff.destroyForcibly();
        }
        assertThat(entries(temporary)).as("what the killed diff left").isNotEmpty();
        Path[] correct = StudentSolution.correct().writeTo(dir.resolve("correct"));

        CliRun next = CliRun.inJvm(dir, List.of("-Djava.io.tmpdir=" + temporary), "grade", "--sphere",
                correct[0].toString(), "--renderer", correct[1].toString(), "--no-sandbox", "--width", "16",
                "--height", "12");

        assertThat(next.status()).as(next.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(entries(temporary)).as("what the killed diff left, after the next grade").isEmpty();
    }

    private static List<Path> entries(Path folder) throws IOException {
        try (Stream<Path> entries = Files.list(folder)) {
            return entries.toList();
        }
    }
}
