package gfx.tick1.command.grade;

import static gfx.tick1.command.grade.GradeCohortTest.files;
import static gfx.tick1.command.grade.GradeCohortTest.gradeArguments;
import static gfx.tick1.command.grade.GradeCohortTest.moodleZip;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.grade.GradeCohortTest.Student;
import gfx.tick1.command.shared.grader.cohort.StoredCode;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A cohort's grade stopped part way (Ctrl-C, SIGTERM): every student graded whole before the stop
 * is kept, the grade says in one line that it stopped and how many results it kept, nothing
 * half-written stays in the report folder, and the same command again grades only the rest.
 */
@ExtendWith(SandboxNeeded.class)
@Order(7)   // one of the longest classes: it starts early (junit-platform.properties)
class GradeCohortStopTest {

    /** Time for the slow student to pass. */
    private static final String[] TIME_LIMIT = {"--time-limit", "60"};

    @TempDir
    Path dir;

    /**
     * Two correct students (and the twin of one), then a slow one, graded one at a time and stopped
     * while the slow one's code runs: the two graded whole are kept, and the same command again
     * grades the slow one alone.
     */
    @Test
    void aStopKeepsEveryStudentGradedWholeAndTheNextRunGradesOnlyTheRest() throws Exception {
        Stopped stop = stopped("TERM");

        assertThat(stop.results()).as("results kept: " + stop.said()).hasSize(2);
        CliRun again = CliRun.of(gradeArguments(stop.zip(), stop.report(), TIME_LIMIT));
        assertThat(again.out()).as(again.transcript()).contains("(1 now, 3 from earlier runs)");
        assertThat(stop.exitValue()).as("the stopped grade's exit status").isNotZero();
    }

    /**
     * A grade stopped with SIGINT (Ctrl-C) or SIGTERM: one line says it stopped and how many
     * results it kept, and the report folder and the temporary folder hold nothing half-written.
     */
    @ParameterizedTest
    @CsvSource({"INT, 1 of 2", "TERM, 3 of 4"})
    void aStopSaysInOneLineHowManyResultsAreKeptAndLeavesNothingHalfWritten(String signal, String kept)
            throws Exception {
        assumeThat(!"INT".equals(signal) || !sigintIgnored()).as("SIGINT is not ignored here (the tests run in "
                + "the foreground), so the grade's JVM can be stopped with it").isTrue();

        Stopped stop = stopped(signal);

        assertThat(stop.said().lines().filter(line -> line.startsWith("tick1 grade: stopped")))
                .as("what the stopped grade said:\n" + stop.said())
                .containsExactly("tick1 grade: stopped: the results of " + kept + " submissions are kept in "
                        + stop.report().resolve(CohortCommand.STATE_FOLDER) + "; run the same command again to "
                        + "grade the rest and write the report");
        assertThat(stop.said()).as("what the stopped grade said").doesNotContain("internal error", "Exception");
        assertThat(stop.stateFolder()).as("half-written results").noneMatch(name -> name.startsWith("."));
        assertThat(stop.leftInTemporaryFolder()).as("work folders and filter files").isEmpty();
    }

    /**
     * The twin of a correct student (the same files, graded once, for both) is kept with the result it shares, and
     * the stop line counts both: two results stored, three submissions kept.
     */
    @Test
    void aStopCountsTheTwinOfAStudentGradedWholeAsKept() throws Exception {
        Stopped stop = stopped("TERM");

        assertThat(stop.results()).as("results stored: " + stop.said()).hasSize(2);
        assertThat(stop.said().lines().filter(line -> line.startsWith("tick1 grade: stopped"))).as(stop.said())
                .singleElement().asString().startsWith("tick1 grade: stopped: the results of 3 of 4 submissions are "
                        + "kept");
    }

    /**
     * A grade stopped with SIGINT before any student's grade began (while the sandbox is being made: its bubblewrap
     * here waits before it runs) says so in the one stop line, as a later stop does.
     */
    @Test
    void aStopBeforeAnyStudentsGradeBeganSaysInOneLineThatItStopped() throws Exception {
        assumeThat(!sigintIgnored()).as("SIGINT is not ignored here (the tests run in the foreground), so the grade's "
                + "JVM can be stopped with it").isTrue();
        SlowBubblewrap bubblewrap = SlowBubblewrap.in(dir);
        Process grade = GradeCohortTest.gradeInAJvmOfItsOwn(dir, List.of(bubblewrap.jvmOption()),
                gradeArguments(moodleZip(dir.resolve("download.zip"), List.of(slow("Slow", 102, SLOW_RENDER))),
                        dir.resolve("report")));
        bubblewrap.awaitBegun(grade);
        List<ProcessHandle> waiting = grade.descendants().toList();

        new ProcessBuilder("/bin/kill", "-INT", Long.toString(grade.pid())).start().waitFor();
        assertThat(grade.waitFor(60, TimeUnit.SECONDS)).as("the grade ended").isTrue();
        waiting.forEach(ProcessHandle::destroy);

        String said = Files.readString(dir.resolve("grade.log"));
        assertThat(said.lines().filter(line -> line.startsWith("tick1 grade: stopped"))).as(said).singleElement()
                .asString().contains("before any submission was graded");
    }

    /**
     * Nothing the grade prints comes after the stopped line: here, with each run's output folder on the host's
     * disk, the warning that says so, which a grade prints at its end.
     */
    @Test
    void theStoppedLineIsTheLastLineTheGradePrints() throws Exception {
        Path zip = moodleZip(dir.resolve("download.zip"), List.of(slow("Slow", 102, SLOW_RENDER)));
        Process grade = GradeCohortTest.gradeInAJvmOfItsOwn(dir, List.of("-Dtick1.grade.outputDisks=host"),
                gradeArguments(zip, dir.resolve("report"), "--jobs", "1", TIME_LIMIT[0], TIME_LIMIT[1]));
        awaitTheSlowCode(dir, grade, dir.resolve("report").resolve(CohortCommand.STATE_FOLDER), 0, 1);
        new ProcessBuilder("/bin/kill", "-TERM", Long.toString(grade.pid())).start().waitFor();
        assertThat(grade.waitFor(120, TimeUnit.SECONDS)).as("the grade ended").isTrue();

        String said = Files.readString(dir.resolve("grade.log"));
        assertThat(said.lines().filter(line -> !line.isBlank())).as("what the stopped grade said:%n%s", said)
                .last().asString().startsWith("tick1 grade: stopped: ");
    }

    /**
     * A grade stopped with a signal while a slow student's code ran, as it was when it ended: what it said, its exit
     * status, and the names in its state folder and its temporary folder. SIGTERM's stop, which three tests read,
     * is of two correct students, the twin of one, and a slow one; SIGINT's, of a correct student and a slow one.
     */
    private record Stopped(Path zip, Path report, String said, int exitValue, List<String> stateFolder,
            List<String> leftInTemporaryFolder) {

        List<String> results() {
            return stateFolder.stream().filter(name -> !name.startsWith(".")).toList();
        }
    }

    @TempDir
    static Path stops;
    private static final Map<String, Stopped> STOPPED = new HashMap<>();

    /** The grade stopped with {@code signal}, stopped once for all the tests that read it. */
    private static synchronized Stopped stopped(String signal) throws Exception {
        Stopped stop = STOPPED.get(signal);
        if (stop == null) {
            // The sandbox's user passes through the folders above each grade's own (gradeInAJvmOfItsOwn).
            Files.setPosixFilePermissions(stops, PosixFilePermissions.fromString("rwx--x--x"));
            Path folder = Files.createTempDirectory(stops, signal);
            boolean term = "TERM".equals(signal);
            Path zip = moodleZip(folder.resolve("download.zip"), term ? twoCorrectATwinThenOneSlow()
                    : List.of(twoCorrectATwinThenOneSlow().get(0), slow("Slow", 102, SLOW_RENDER)));
            Path report = folder.resolve("report");
            Process grade = stoppedWhileTheSlowOneRuns(folder, zip, report, signal, term ? 2 : 1);
            stop = new Stopped(zip, report, Files.readString(folder.resolve("grade.log")), grade.exitValue(),
                    names(report.resolve(CohortCommand.STATE_FOLDER)), names(folder.resolve("tmp")));
            STOPPED.put(signal, stop);
        }
        return stop;
    }

    private static List<String> names(Path folder) throws IOException {
        try (Stream<Path> entries = Files.list(folder)) {
            return entries.map(path -> path.getFileName().toString()).toList();
        }
    }

    /**
     * A grade killed with SIGKILL while two slow students' code runs, two jobs at a time, leaves its
     * work folder, the tmpfs of those runs and of each job's compiler, and control groups: the next
     * grade, with the same temporary folder (of another download), removes them all before it grades.
     */
    @Test
    void whatAKilledGradeLeftIsRemovedByTheNextGrade() throws Exception {
        // Never waited out: the grade is killed while both wait.
        List<Student> slow = List.of(slow("Slow 0", 200, KILLED_RENDER), slow("Slow 1", 201, KILLED_RENDER));
        Path zip = moodleZip(dir.resolve("download.zip"), slow);
        Path report = dir.resolve("report");
        Process killed = GradeCohortTest.gradeInAJvmOfItsOwn(dir, gradeArguments(zip, report, "--jobs", "2",
                TIME_LIMIT[0], TIME_LIMIT[1]));
        awaitTheSlowCode(dir, killed, report.resolve(CohortCommand.STATE_FOLDER), 0, 2);
        killed.destroyForcibly().waitFor();
        try (Stream<Path> left = Files.list(dir.resolve("tmp"))) {
            assertThat(left).as("what the killed grade left in its temporary folder").isNotEmpty();
        }

        // Its one student's Renderer.java is missing: nothing is run, and what the grade removes is all it does.
        Map<String, byte[]> sphereAlone = new HashMap<>(files(StudentSolution.correct()));
        sphereAlone.remove("Renderer.java");
        Path another = moodleZip(dir.resolve("another.zip"), List.of(new Student("Missing Renderer", 100, sphereAlone,
                false)));
        Process next = GradeCohortTest.gradeInAJvmOfItsOwn(dir, gradeArguments(another, dir.resolve("another"),
                "--no-lookalikes"));
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

    /**
     * How long a slow student's render of tick1.xml waits, in seconds: long enough to stop a grade of one student at
     * a time while it runs, which the test does as soon as it runs; and the one wait of a run after the stop.
     */
    private static final int SLOW_RENDER = 5;
    /** As long, for two jobs' slow students to run at once however far apart they begin: never waited out. */
    private static final int KILLED_RENDER = 40;

    /** Two correct students, the twin of the first (the same files), then a slow one. */
    private static List<Student> twoCorrectATwinThenOneSlow() {
        List<Student> students = new ArrayList<>();
        for (int i = 0; i < 2; i++) {
            Map<String, byte[]> own = files(StudentSolution.correct().editRenderer("return image;",
                    "return image; // " + i));
            students.add(new Student("Correct " + i, 100 + i, own, true));
            if (i == 0) {
                students.add(new Student("Correct 0 Again", 110, own, true));
            }
        }
        students.add(slow("Slow", 102, SLOW_RENDER));
        return students;
    }

    /**
     * A student whose render of tick1.xml waits {@code seconds}, once in each JVM that runs it, and then passes; the
     * render of the hidden scene does not wait (tick1.xml's light is right of the camera, the hidden scene's left).
     */
    private static Student slow(String name, int id, int seconds) {
        return new Student(name, id, files(StudentSolution.correct()
                .editRenderer("public class Renderer {", "public class Renderer {\n    // " + name
                        + "\n    private static boolean waited;")
                .editRenderer("return image;", "if (!waited && scene.getPointLight().getPosition().x > 0) { "
                        + "waited = true; try { Thread.sleep(" + seconds * 1000 + "); } "
                        + "catch (InterruptedException e) { } } return image;")), true);
    }

    /**
     * The grade of {@code zip}, one student at a time, in a JVM of its own whose folder is {@code dir}, stopped
     * with {@code signal} once the correct students' {@code stored} results are stored and the slow one's code
     * runs; ended.
     */
    private static Process stoppedWhileTheSlowOneRuns(Path dir, Path zip, Path report, String signal, int stored)
            throws Exception {
        Process grade = GradeCohortTest.gradeInAJvmOfItsOwn(dir, gradeArguments(zip, report, "--jobs", "1",
                TIME_LIMIT[0], TIME_LIMIT[1]));
        awaitTheSlowCode(dir, grade, report.resolve(CohortCommand.STATE_FOLDER), stored, 1);
        new ProcessBuilder("/bin/kill", "-" + signal, Long.toString(grade.pid())).start().waitFor();
        assertThat(grade.waitFor(120, TimeUnit.SECONDS)).as("the grade ended").isTrue();
        return grade;
    }

    /**
     * Waits (at most two minutes) for {@code stored} results to be stored (the correct students') and {@code slow}
     * slow students' code to run: as many JVMs (not the bubblewrap around each) that run the harness's render.
     */
    private static void awaitTheSlowCode(Path dir, Process grade, Path state, int stored, int slow)
            throws IOException, InterruptedException {
        for (int i = 0; i < 1200 && grade.isAlive() && !(storedResults(state) == stored && grade.descendants()
                .map(p -> p.info().commandLine().orElse("")).filter(line -> line.contains("StudentHarness render")
                        && line.split(" ", 2)[0].endsWith("/java")).count() >= slow); i++) {
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
            return entries.filter(p -> !p.getFileName().toString().startsWith(".")
                    && !p.getFileName().toString().equals(StoredCode.FOLDER)).count();
        }
    }

    /** Whether this process ignores SIGINT, as a shell's background job does: the grade's JVM then ignores it too. */
    private static boolean sigintIgnored() throws IOException {
        return Files.readAllLines(Path.of("/proc/self/status")).stream().filter(line -> line.startsWith("SigIgn:"))
                .anyMatch(line -> (Long.parseLong(line.substring(7).strip(), 16) & 2) != 0);
    }
}
