package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.harness.AnswerLog;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

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

    @Test
    void callsLeftUnmadeForWantOfAThreadAreNotSaidToDifferFromOurs(@TempDir Path folder) throws Exception {
        String log = CalledSolution.correct().probeLog(folder);
        // The log as the harness leaves it when the random shadings' call finds no thread: every line up to the
        // phong line, then the line that says the calls left were never made.
        int phong = log.indexOf("\nphong ") + 1;
        String cut = log.substring(0, log.indexOf('\n', phong) + 1) + AnswerLog.NO_THREAD + "\n";

        BehaviourFindings findings = BehaviourFindings.of(cut);

        assertThat(findings.facts()).as("the findings of correct methods whose last calls found no thread")
                .isEmpty();
    }

    @Test
    void aLogThatEndsForWantOfAThreadSaysSoWhereNoMethodDiffers(@TempDir Path folder) throws Exception {
        String log = CalledSolution.correct().probeLog(folder);
        String cut = log.substring(0, log.indexOf('\n') + 1) + AnswerLog.NO_THREAD + "\n";

        assertThat(BehaviourFindings.of(cut).noFinding()).as("what is said of methods whose calls found no thread")
                .isEqualTo("your intersectionWith and illuminate could not be checked: the program reached the limit "
                        + "of processes and threads, so no thread was left to call your methods in");
    }
}
