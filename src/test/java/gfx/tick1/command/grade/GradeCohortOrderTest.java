package gfx.tick1.command.grade;

import static gfx.tick1.command.grade.GradeCohortTest.files;
import static gfx.tick1.command.grade.GradeCohortTest.gradeArguments;
import static gfx.tick1.command.grade.GradeCohortTest.moodleZip;
import static gfx.tick1.command.grade.GradeCohortTest.resource;
import static gfx.tick1.command.grade.GradeCohortTest.rows;
import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.grade.GradeCohortTest.Student;
import gfx.tick1.command.shared.grader.sandbox.SandboxProperties;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * The order a cohort's runs go in: every submission's public run before any submission's hidden
 * run, so that the runs whose reports students see never come after a run that had a hidden
 * scene, nor run beside one; and what a grade keeps on the grader's disk between its two runs.
 */
@ExtendWith(SandboxNeeded.class)
@SandboxProperties.Read
class GradeCohortOrderTest {

    /**
     * Two students whose tick1.xml runs quote the time of day, and whose hidden runs each sleep
     * 20 s, the length a hidden run would choose to carry what its scene holds to the next grade,
     * graded one at a time. Were a student's grade whole before the next began, one quoted time
     * would be at least 20 s after the other; the public runs all come first, so they are seconds
     * apart. (The times only tell the order: no speed is asserted.)
     */
    @Test
    void everyPublicRunOfACohortComesBeforeAnyHiddenRunSoNoneCanTimeOne(@TempDir Path dir) throws IOException {
        String timer = resource("/students/attacks/time-the-hidden-run/Renderer.java");
        String sphere = StudentSolution.correct().sphere();
        List<Student> students = List.of(
                new Student("First Timer", 1, files(new StudentSolution(sphere, timer)), false),
                new Student("Second Timer", 2, files(new StudentSolution(sphere, timer + "// the second\n")), false));
        Path report = dir.resolve("report");

        CliRun run = CliRun.of(gradeArguments(moodleZip(dir.resolve("timers.zip"), students), report,
                "--jobs", "1", "--time-limit", "60"));

        List<Long> quoted = new ArrayList<>();
        for (Student student : students) {
            String feedback = Files.readString(report.resolve("feedback").resolve(student.folder())
                    .resolve("feedback.txt"));
            Matcher clock = Pattern.compile("clock: \\[(\\d+)]").matcher(feedback);
            assertThat(clock.find()).as(student.name() + "'s feedback quotes its public run's time:\n" + feedback
                    + run.transcript()).isTrue();
            quoted.add(Long.parseLong(clock.group(1)));
        }
        assertThat(Math.abs(quoted.get(1) - quoted.get(0))).as("the milliseconds between the two public runs' "
                + "times: under 20,000, so neither ran after the other's hidden run").isLessThan(15_000);
    }

    /**
     * A correct solution with more class files than a grade keeps on the grader's disk while it
     * waits for its hidden run: its classes are deleted after the public run and compiled again
     * for the hidden one, which passes.
     */
    @Test
    void aSolutionWithTooManyClassesToKeepBetweenItsRunsIsCompiledAgainAndPasses(@TempDir Path dir)
            throws IOException {
        StringBuilder many = new StringBuilder();
        for (int i = 0; i < 250; i++) {
            many.append("    static final class Extra").append(i).append(" { }\n");
        }
        StudentSolution correct = StudentSolution.correct();
        StudentSolution manyClasses = correct.editRenderer(RENDER_CLASS, RENDER_CLASS + many);
        assertThat(manyClasses.renderer()).as("the solution with 250 more classes").contains("Extra249");
        List<Student> students = List.of(new Student("Many Classes", 1, files(manyClasses), true));
        Path report = dir.resolve("report");

        CliRun run = CliRun.of(gradeArguments(moodleZip(dir.resolve("many.zip"), students), report));

        assertThat(rows(report).get("Participant 1")).as(run.transcript()).element(4).isEqualTo("1.00");
    }

    /** The line of the correct solution's Renderer.java that its class's members follow. */
    private static final String RENDER_CLASS = "public class Renderer {\n";
}
