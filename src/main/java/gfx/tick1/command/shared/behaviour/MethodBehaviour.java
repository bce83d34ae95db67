package gfx.tick1.command.shared.behaviour;

import java.util.List;

/**
 * How one of the student's two methods behaved on the inputs of
 * {@link gfx.tick1.command.shared.grader.harness.BehaviourInputs} that the course's scenes can show
 * (the tested edge cases, then the random inputs, in that order), compared with ours.
 *
 * @param method     "intersectionWith" or "illuminate"
 * @param inputs     how many tested inputs it was called on
 * @param difference where and how its answers differ from ours ({@link Difference#NONE} when they do not)
 * @param untested   notes on what the course's scenes cannot show, each beginning with
 *                   {@link BehaviourJudge#UNTESTED}
 * @param ruledOut   the catalogue's mistakes of this method whose models answer otherwise than it on a
 *                   tested input: none of them is what it does
 * @param notAlone   the catalogue's mistakes of render, drawn with our answers of this method, that cannot be
 *                   the whole of an image: on an input where its answer is visibly not ours, it is not one
 *                   such a mistake made here either
 */
public record MethodBehaviour(String method, int inputs, Difference difference, List<String> untested,
        List<Variant> ruledOut, List<Variant> notAlone) {

    /**
     * Where and how a method's answers differ from ours.
     *
     * @param differing      the indices, in order, of the inputs where its answer is not ours
     * @param mistake        the catalogue's entries whose model reproduces every answer: one, two together,
     *                       or none (not recognised, or nothing differs)
     * @param counterexample the simplest input where it differs, its answer and ours, in words; null when none
     * @param properties     facts checked on its answers alone ("the normal you return has length 2")
     */
    public record Difference(List<Integer> differing, List<Variant> mistake, String counterexample,
            List<String> properties) {

        /** Every answer is ours. */
        public static final Difference NONE = new Difference(List.of(), List.of(), null, List.of());
    }

    /** Whether every tested answer is ours, within the tolerance. */
    public boolean behavesAsOurs() {
        return difference.differing().isEmpty();
    }
}
