package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.diagnosis.Variant;
import java.util.List;

/**
 * How one of the student's two methods behaved on the inputs of
 * {@link gfx.tick1.command.shared.grader.harness.ProbeCalls} that the course's scenes can show
 * (the tested edge cases, then the random inputs, in that order), compared with ours.
 *
 * @param method         "intersectionWith" or "illuminate"
 * @param inputs         how many tested inputs it was called on
 * @param differing      the indices, in that order, of the inputs where its answer is not ours
 * @param mistake        the catalogue's entries whose model reproduces every answer: one, two together,
 *                       or none (not recognised, or nothing differs)
 * @param counterexample the simplest input where it differs, its answer and ours, in words; null when none
 * @param properties     facts checked on its answers alone ("the normal you return has length 2")
 * @param untested       notes on what the course's scenes cannot show, each beginning with
 *                       {@link BehaviourJudge#UNTESTED}
 */
public record MethodBehaviour(String method, int inputs, List<Integer> differing, List<Variant> mistake,
        String counterexample, List<String> properties, List<String> untested) {

    /** Whether every tested answer is ours, within the tolerance. */
    public boolean behavesAsOurs() {
        return differing.isEmpty();
    }
}
