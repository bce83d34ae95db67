package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.harness.AnswerLog;
import org.junit.jupiter.api.Test;

/** Why the behaviour comparison did not run is said as the probes' log shows it. */
class BehaviourFindingsTest {

    @Test
    void probesThatFoundNoThreadAreSaidToHaveReachedTheLimitOfProcessesAndThreads() {
        BehaviourFindings findings = BehaviourFindings.of(AnswerLog.NO_THREAD + "\n");

        assertThat(findings.ran()).as("whether a log of no answer but the missing thread ran the comparison")
                .isFalse();
        assertThat(findings.whyNotRan()).as("why a log whose first call found no thread has no answer")
                .isEqualTo("the program reached the limit of processes and threads, so no thread was left to call "
                        + "your methods in");
    }

    @Test
    void probesThatLoggedNothingGaveNoAnswer() {
        assertThat(BehaviourFindings.of("").whyNotRan()).as("why an empty log has no answer")
                .isEqualTo("your methods gave no answer");
    }
}
