package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.kit.StarterKit;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The one-student section's shape: the bare pipeline first, then each of a student's runs with its ratio to it, its
 * goal and its memory. What the numbers are is the run's business: the rows here are made up.
 */
class OneStudentSectionTest {

    private static final OneStudentSection.Measured MEASURED = new OneStudentSection.Measured(5, List.of(
            new OneStudentSection.Row(OneStudentSection.Kind.BARE, 4.0, 120),
            new OneStudentSection.Row(OneStudentSection.Kind.GRADE, 3.0, 180),
            new OneStudentSection.Row(OneStudentSection.Kind.GRADE_WRONG, 6.0, 230),
            new OneStudentSection.Row(OneStudentSection.Kind.DIFF, 1.0, 150),
            new OneStudentSection.Row(OneStudentSection.Kind.VPL, 3.2, 170)), null,
            "0.52 before the runs and 0.61 after them");

    @Test
    void eachRunHasItsMedianItsRatioToTheBarePipelineItsGoalAndItsMemory() {
        String section = OneStudentSection.markdown(MEASURED, false);
        assertThat(section).contains("## One student", "5 runs of each, taken in turn",
                "load average (1 minute) was 0.52 before the runs and 0.61 after them",
                "| run | median s | ratio to the bare pipeline | goal | met | peak MiB |")
                .contains("| the bare pipeline: javac of the starter kit with the correct solution, then "
                        + "`java gfx.tick1.Tick1` on tick1.xml and on the hidden scene, no sandbox | 4.00 | 1.00 |  |  "
                        + "| 120 |")
                .contains("| `tick1 grade`, correct solution | 3.00 | 0.75 | at most 1.0 | yes | 180 |")
                .contains("| `tick1 grade`, wrong solution (N.L not clamped), with its explanation | 6.00 | 1.50 | "
                        + "at most 1.3 | no | 230 |")
                .contains("| `tick1 diff`, the correct solution | 1.00 | 0.25 | at most 0.5 | yes | 150 |")
                .contains("| `tick1 grade --format vpl`, correct solution, as VPL's activity starts it with VPL's "
                        + "default limits (tick1's heap 160 MiB, the student's 64 MiB) | 3.20 | 0.80 | "
                        + "at most 1.0 | yes | 170 |");
    }

    @Test
    void theVplEvaluationsMemoryIsSetAgainstVplsLimit() {
        assertThat(OneStudentSection.markdown(MEASURED, false))
                .contains("The summed memory of a VPL evaluation of honest code: 170 MiB, against VPL's default "
                        + "limit of 256 MiB (yes).");
    }

    @Test
    void aQuickRunCallsNoGoalMetOrUnmet() {
        String section = OneStudentSection.markdown(MEASURED, true);
        assertThat(section).contains("not a verdict").doesNotContain("| yes |", "| no |", "(yes)", "(no)");
    }

    @Test
    void aSectionThatCouldNotBeMeasuredSaysWhyAndHasNoTable() {
        String section = OneStudentSection.markdown(new OneStudentSection.Measured(5, List.of(),
                "tick1 grade ... exited with 2: bubblewrap is not installed", null), false);
        assertThat(section).contains("## One student", "Not measured: tick1 grade ... exited with 2: bubblewrap is "
                + "not installed.").doesNotContain("| run |");
    }

    @Test
    void theConsoleHasALineForEachRun() {
        StringWriter console = new StringWriter();
        OneStudentSection.print(MEASURED, new PrintWriter(console));
        assertThat(console.toString().lines()).as("the console").hasSize(6)
                .anySatisfy(line -> assertThat(line).contains("grade, wrong", "1.50", "at most 1.3", "230 MiB"));
    }

    @Test
    void theCorrectSolutionDiffersFromOursInTextAndTheWrongOneInTheDiffuseClamp() {
        String ours = StarterKit.solution("Renderer");
        assertThat(StudentSolutions.correctRenderer()).as("the correct solution in a student's words")
                .isNotEqualTo(ours).contains(StudentSolutions.DIFFUSE_OWN_WORDS)
                .doesNotContain(StudentSolutions.DIFFUSE);
        assertThat(StudentSolutions.wrongRenderer()).as("the wrong solution")
                .contains(StudentSolutions.DIFFUSE_NOT_CLAMPED).doesNotContain(StudentSolutions.DIFFUSE);
    }
}
