package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The benchmark's cohort section says what was measured, through which command, and sets no target. */
class CohortSectionTest {

    private static final CohortTiming.Measured MEASURED = new CohortTiming.Measured(100, 2, 100, 80.0, 1.6);

    @Test
    void theSectionGivesTheWallTimePerSubmissionAndTheMedianSubmissionsTime() {
        String section = CohortSection.markdown(MEASURED);
        assertThat(section).startsWith("## Grading a cohort")
                .contains("`tick1 grade --submissions` with its defaults, in a fresh process")
                .contains("100 correct solutions", "2 at a time", "100 of 100 passed")
                .contains("| wall time per submission (whole grade / submissions) | 0.800 |")
                .contains("| whole grade, wall | 80.0 |")
                .contains("| median of the submissions' times in the report (one job's view) | 1.600 |");
    }

    @Test
    void theSectionSetsNoTarget() {
        assertThat(CohortSection.markdown(MEASURED).toLowerCase()).doesNotContain("target", "goal", "pass:", "fail:");
    }

    @Test
    void theMedianOfAnEvenCountIsTheMeanOfTheMiddleTwo() {
        assertThat(CohortTiming.median(new long[] {4, 1, 3, 2})).as("the median of 1, 2, 3, 4").isEqualTo(2.5);
        assertThat(CohortTiming.median(new long[0])).as("the median of none").isNaN();
    }
}
