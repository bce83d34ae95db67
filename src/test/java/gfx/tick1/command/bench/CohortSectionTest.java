package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The benchmark's cohort section says what was measured, with every phase, and sets no target. */
class CohortSectionTest {

    private static final CohortTiming.Measured MEASURED = new CohortTiming.Measured(100, 2, 100, 80.0,
            new CohortTiming.Medians(0.9, 0.6, 0.05, 1.6), new CohortTiming.Overheads(0.0042, 0.0087, 0.0311));

    @Test
    void theSectionGivesTheWallTimePerSubmissionAndEachPhase() {
        String section = CohortSection.markdown(MEASURED);
        assertThat(section).startsWith("## Grading a cohort")
                .contains("100 correct solutions", "2 at a time", "100 of 100 passed")
                .contains("| wall time per submission (whole grade / submissions) | 0.800 |")
                .contains("compile (by the job's warm compiler, in the sandbox) | 0.900 |")
                .contains("| 0.600 |", "| 0.050 |", "| 1.600 |")
                .contains("the control groups (2 runs, each making, joining, removing one)", "| 0.0042 |")
                .contains("the output folders' file systems (2 runs, each mounting, counting, unmounting one) "
                        + "| 0.0087 |")
                .contains("the JDK's files and libraries, each bound on its own and read into memory before the run "
                        + "(2 runs) | 0.0311 |");
    }

    @Test
    void theSectionSetsNoTarget() {
        assertThat(CohortSection.markdown(MEASURED).toLowerCase()).doesNotContain("target", "goal", "pass:", "fail:");
    }
}
