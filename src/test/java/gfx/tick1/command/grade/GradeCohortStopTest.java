package gfx.tick1.command.grade;

import static gfx.tick1.command.grade.GradeCohortTest.files;
import static gfx.tick1.command.grade.GradeCohortTest.gradeArguments;
import static gfx.tick1.command.grade.GradeCohortTest.moodleZip;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.grade.GradeCohortTest.Student;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import gfx.tick1.command.shared.grader.sandbox.SandboxProperties;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A cohort's grade stopped part way (Ctrl-C, SIGTERM): every student graded whole before the stop
 * is kept, the grade says in one line that it stopped and how many results it kept, nothing
 * half-written stays in the report folder, and the same command again grades only the rest.
 */
@ExtendWith(SandboxNeeded.class)
@SandboxProperties.Read
class GradeCohortStopTest {

    /** Time for the slow student to pass. */
    private static final String[] TIME_LIMIT = {"--time-limit", "60"};

    @TempDir
    Path dir;

    /**
     * Two correct students, then one whose render waits 15 s, graded one at a time and stopped
     * while the third's code runs: the first two, graded whole, are kept, and the same command
     * again grades the third alone.
     */
    @Test
    void aStopKeepsEveryStudentGradedWholeAndTheNextRunGradesOnlyTheRest() throws Exception {
        Path zip = moodleZip(dir.resolve("download.zip"), twoCorrectThenOneSlow());
        Path report = dir.resolve("report");
        Process grade = stoppedWhileTheThirdRuns(zip, report, "TERM");

        assertThat(storedResults(report.resolve(CohortCommand.STATE_FOLDER))).as("results kept: "
                + Files.readString(dir.resolve("grade.log"))).isEqualTo(2);
        CliRun again = CliRun.of(gradeArguments(zip, report, TIME_LIMIT));
        assertThat(again.out()).as(again.transcript()).contains("(1 now, 2 from earlier runs)");
        assertThat(grade.exitValue()).as("the stopped grade's exit status").isNotZero();
    }

    /**
     * The same grade stopped with SIGINT (Ctrl-C) or SIGTERM: one line says it stopped and how
     * many results it kept, and the report folder and the temporary folder hold nothing
     * half-written.
     */
    @ParameterizedTest
    @ValueSource(strings = {"INT", "TERM"})
    void aStopSaysInOneLineHowManyResultsAreKeptAndLeavesNothingHalfWritten(String signal) throws Exception {
        assumeThat(!"INT".equals(signal) || !sigintIgnored()).as("SIGINT is not ignored here (the tests run in "
                + "the foreground), so the grade's JVM can be stopped with it").isTrue();
        Path report = dir.resolve("report");

        stoppedWhileTheThirdRuns(moodleZip(dir.resolve("download.zip"), twoCorrectThenOneSlow()), report,
                signal);

        String said = Files.readString(dir.resolve("grade.log"));
        assertThat(said.lines().filter(line -> line.startsWith("tick1 grade: stopped")))
                .as("what the stopped grade said:\n" + said)
                .containsExactly("tick1 grade: stopped: the results of 2 of 3 submissions are kept in "
                        + report.resolve(CohortCommand.STATE_FOLDER) + "; run the same command again to grade the "
                        + "other 1 and write the report");
        assertThat(said).as("what the stopped grade said").doesNotContain("internal error", "Exception");
        try (Stream<Path> left = Files.list(report.resolve(CohortCommand.STATE_FOLDER))) {
            assertThat(left.map(path -> path.getFileName().toString())).as("half-written results")
                    .noneMatch(name -> name.startsWith("."));
        }
        try (Stream<Path> left = Files.list(dir.resolve("tmp"))) {
            assertThat(left).as("work folders and filter files").isEmpty();
        }
    }

    /**
     * A grade killed with SIGKILL while the slow student's code runs, two jobs at a time, leaves its
     * work folder, the tmpfs of that run and of each job's compiler, and control groups: the next
     * grade, with the same temporary folder, removes them all before it grades.
     */
    @Test
    void whatAKilledGradeLeftIsRemovedByTheNextGrade() throws Exception {
        Path zip = moodleZip(dir.resolve("download.zip"), twoCorrectThenOneSlow());
        Path report = dir.resolve("report");
        Process killed = GradeCohortTest.gradeInAJvmOfItsOwn(dir, gradeArguments(zip, report, "--jobs", "2",
                TIME_LIMIT[0], TIME_LIMIT[1]));
        awaitTheSlowCode(killed, report.resolve(CohortCommand.STATE_FOLDER));
        killed.destroyForcibly().waitFor();
        try (Stream<Path> left = Files.list(dir.resolve("tmp"))) {
            assertThat(left).as("what the killed grade left in its temporary folder").isNotEmpty();
        }

        Process next = GradeCohortTest.gradeInAJvmOfItsOwn(dir, gradeArguments(zip, report, TIME_LIMIT));
        assertThat(next.waitFor(300, TimeUnit.SECONDS)).as("the next grade ended").isTrue();

        String said = Files.readString(dir.resolve("grade.log"));
        assertThat(next.exitValue()).as(said).isZero();
        try (Stream<Path> left = Files.list(dir.resolve("tmp"))) {
            assertThat(left).as("work folders and filter files, after the next grade").isEmpty();
        }
        assertThat(Files.readAllLines(Path.of("/proc/self/mountinfo"))).as("file systems mounted in the killed "
                + "grade's work folder").noneMatch(line -> line.contains(dir.toString()));
        assertThat(controlGroupsOf(killed.pid())).as("the killed grade's control groups").isEmpty();
    }

    /** The control groups named for the grader whose process id is {@code pid}, anywhere under /sys/fs/cgroup. */
    private static List<Path> controlGroupsOf(long pid) throws IOException {
        Path cgroups = Path.of("/sys/fs/cgroup");
        if (!Files.isDirectory(cgroups)) {
            return List.of();
        }
        try (Stream<Path> found = Files.find(cgroups, 8, (path, attributes) -> attributes.isDirectory()
                && path.getFileName() != null && path.getFileName().toString().startsWith("tick1-" + pid + "-"))) {
            return found.toList();
        }
    }

    /** Two correct students, then one whose render waits 15 s. */
    private static List<Student> twoCorrectThenOneSlow() {
        List<Student> students = new ArrayList<>();
        for (int i = 0; i < 2; i++) {
            students.add(new Student("Correct " + i, 100 + i, files(StudentSolution.correct()
                    .editRenderer("return image;", "return image; // " + i)), true));
        }
        students.add(new Student("Slow", 102, files(StudentSolution.correct().editRenderer("return image;",
                "try { Thread.sleep(15_000); } catch (InterruptedException e) { } return image;")), true));
        return students;
    }

    /**
     * The grade of {@code zip}, one student at a time, in a JVM of its own, stopped with {@code signal}
     * once the two correct students' results are stored and the slow one's code runs; ended.
     */
    private Process stoppedWhileTheThirdRuns(Path zip, Path report, String signal) throws Exception {
        Process grade = GradeCohortTest.gradeInAJvmOfItsOwn(dir, gradeArguments(zip, report, "--jobs", "1",
                TIME_LIMIT[0], TIME_LIMIT[1]));
        awaitTheSlowCode(grade, report.resolve(CohortCommand.STATE_FOLDER));
        new ProcessBuilder("/bin/kill", "-" + signal, Long.toString(grade.pid())).start().waitFor();
        assertThat(grade.waitFor(120, TimeUnit.SECONDS)).as("the grade ended").isTrue();
        return grade;
    }

    /**
     * Waits (at most two minutes) for the two correct students' results to be stored and the
     * slow student's code to run.
     */
    private void awaitTheSlowCode(Process grade, Path state) throws IOException, InterruptedException {
        for (int i = 0; i < 1200 && grade.isAlive() && !(storedResults(state) == 2 && grade.descendants()
                .anyMatch(p -> p.info().commandLine().orElse("").contains("StudentHarness render"))); i++) {
            Thread.sleep(100);
        }
        assertThat(grade.isAlive()).as("the grade runs: " + Files.readString(dir.resolve("grade.log"))).isTrue();
    }

    /** How many whole results {@code state} holds. */
    private static long storedResults(Path state) throws IOException {
        if (!Files.isDirectory(state)) {
            return 0;
        }
        try (Stream<Path> entries = Files.list(state)) {
            return entries.filter(p -> !p.getFileName().toString().startsWith(".")).count();
        }
    }

    /** Whether this process ignores SIGINT, as a shell's background job does: the grade's JVM then ignores it too. */
    private static boolean sigintIgnored() throws IOException {
        return Files.readAllLines(Path.of("/proc/self/status")).stream().filter(line -> line.startsWith("SigIgn:"))
                .anyMatch(line -> (Long.parseLong(line.substring(7).strip(), 16) & 2) != 0);
    }
}
