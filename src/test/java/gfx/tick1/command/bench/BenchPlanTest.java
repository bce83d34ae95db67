package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * The quick run is the full one made smaller in every part, so that it stays cheap on a shared two-core machine:
 * its cost is held here by what it does (frames, repetitions, fresh processes, the cohort), never by a time.
 */
class BenchPlanTest {

    private static final BenchPlan QUICK = BenchPlan.QUICK, FULL = BenchPlan.FULL;

    @Test
    void theQuickRunRendersSmallerFramesThanTheFullRun() {
        assertThat((long) QUICK.width() * QUICK.height()).as("the in-process tick1.xml frame")
                .isLessThan((long) FULL.width() * FULL.height());
        assertThat(QUICK.errorWidth()).as("the frame errors are measured on").isLessThan(FULL.errorWidth());
        assertThat(QUICK.crowdWidth()).as("the crowd's frame").isLessThan(FULL.crowdWidth());
        assertThat((long) QUICK.bigWidth() * QUICK.bigHeight()).as("the C yardstick's frame")
                .isLessThan((long) FULL.bigWidth() * FULL.bigHeight());
    }

    @Test
    void theQuickRunRepeatsLessThanTheFullRun() {
        assertThat(QUICK.warmups()).as("in-process warm-up frames").isLessThan(FULL.warmups());
        assertThat(QUICK.runs()).as("in-process timed frames").isLessThan(FULL.runs());
        assertThat(QUICK.crowds()).as("the crowds").hasSizeLessThan(FULL.crowds().size());
        assertThat(QUICK.cohort()).as("the cohort").isLessThan(FULL.cohort());
        assertThat(QUICK.studentRuns()).as("one student's runs of each kind").isEqualTo(1)
                .isLessThan(FULL.studentRuns());
    }

    /** A fresh JVM costs about as much CPU as the whole in-process part of a quick run spends on one variant. */
    @Test
    void theQuickRunTimesEachFreshProcessOnceWithNoUntimedRunBeforeIt() {
        assertThat(QUICK.warmUpProcesses()).as("an untimed run before each command").isFalse();
        assertThat(QUICK.singleRuns()).as("timed runs of each fresh process").isEqualTo(1);
        assertThat(QUICK.bigRuns()).as("timed runs of tick1 and the C tracer at the big frame").isEqualTo(1);
        assertThat(QUICK.pairedRuns()).as("timed runs of tick1 and the course code, in turn")
                .isEqualTo(2).isLessThan(FULL.pairedRuns());
    }

    /** Each of the two jobs of a two-core machine grades at least one submission, so the grade's every part runs. */
    @Test
    void theQuickCohortGivesEachOfTwoJobsASubmission() {
        assertThat(QUICK.cohort()).as("the quick cohort").isGreaterThanOrEqualTo(2);
    }
}
