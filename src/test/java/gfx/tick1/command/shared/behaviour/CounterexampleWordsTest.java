package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.harness.BehaviourInputs;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs.Phong;
import gfx.tick1.engine.math.Vector3;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A counterexample states what the student's method returned and what ours returns, in numbers a
 * reader can tell apart: where seven significant digits would print the same two answers (float
 * arithmetic is about 1e-8 off), every digit is printed.
 */
class CounterexampleWordsTest {

    @Test
    void answersApartOnlyBeyondTheSeventhDigitArePrintedWithEveryDigit() {
        BehaviourInputs.IlluminationCall call = BehaviourInputs.ILLUMINATIONS.stream()
                .filter(each -> new BehaviourJudge.ShadeCase(each, null, Phong.FIXED).model(BehaviourJudge.OURS).x
                        > 0.1)
                .findFirst().orElseThrow();
        Vector3 reference = new BehaviourJudge.ShadeCase(call, null, Phong.FIXED).model(BehaviourJudge.OURS);
        // 1e-8 off in one channel, as float arithmetic leaves it: past the tolerance, within seven digits.
        double[] floatSlip = {Math.nextUp(reference.x + 1e-8), reference.y, reference.z};
        String words = new BehaviourJudge.ShadeCase(call, new Answers.Colour(floatSlip), Phong.FIXED).counterexample();

        String yours = words.substring(words.indexOf(", yours returns ") + ", yours returns ".length(),
                words.indexOf("; ours returns "));
        String ours = words.substring(words.indexOf("; ours returns ") + "; ours returns ".length());
        assertThat(yours).as("the two answers, as printed: %s", words).isNotEqualTo(ours);
    }

    /** The course's fixed shading inputs, simplest first (the order a counterexample is chosen in). */
    private static List<BehaviourJudge.ShadeCase> simplestFirst() {
        List<BehaviourJudge.ShadeCase> calls = new ArrayList<>();
        BehaviourInputs.ILLUMINATIONS.forEach(call -> calls.add(new BehaviourJudge.ShadeCase(call, null, Phong.FIXED)));
        calls.sort(Comparator.comparingDouble(BehaviourJudge.ShadeCase::roughness));
        return calls;
    }

    /** Each input answered with our colour plus {@code offset(i)} in red, i its place simplest first. */
    private static List<BehaviourJudge.ShadeCase> answered(java.util.function.IntToDoubleFunction offset) {
        List<BehaviourJudge.ShadeCase> calls = simplestFirst();
        List<BehaviourJudge.ShadeCase> answered = new ArrayList<>();
        for (int i = 0; i < calls.size(); i++) {
            Vector3 ours = calls.get(i).model(BehaviourJudge.OURS);
            answered.add(new BehaviourJudge.ShadeCase(calls.get(i).call(),
                    new Answers.Colour(new double[] {ours.x + offset.applyAsDouble(i), ours.y, ours.z}), Phong.FIXED));
        }
        return answered;
    }

    @Test
    void theCounterexampleIsTheSimplestInputWhoseAnswerAnImageShowsNotOneBelowALevel() {
        List<BehaviourJudge.ShadeCase> calls = simplestFirst();
        int visibleAt = java.util.stream.IntStream.range(1, calls.size())
                .filter(i -> calls.get(i).model(BehaviourJudge.OURS).x < 0.75).findFirst().orElseThrow();
        // The simplest input is a millionth off (no byte moves); a rougher one, with room for it, a fifth.
        List<BehaviourJudge.ShadeCase> answered = answered(i -> i == 0 ? 1e-6 : i == visibleAt ? 0.2 : 0);
        assertThat(answered.get(0).visible()).as("a millionth moves no byte of the simplest input").isFalse();

        String counterexample = BehaviourJudge.judge("illuminate", answered, Variant.Method.ILLUMINATE, List.of())
                .difference().counterexample();
        assertThat(counterexample).as("the input whose colour is a fifth off")
                .isEqualTo(answered.get(visibleAt).counterexample());
    }

    @Test
    void whenNoDifferenceMovesAByteTheCounterexampleSaysSo() {
        List<BehaviourJudge.ShadeCase> answered = answered(i -> i < 3 ? 1e-6 : 0);
        assertThat(answered.subList(0, 3)).as("no byte moves").noneMatch(BehaviourJudge.ShadeCase::visible);

        String counterexample = BehaviourJudge.judge("illuminate", answered, Variant.Method.ILLUMINATE, List.of())
                .difference().counterexample();
        assertThat(counterexample).as("the simplest, said to be below a level")
                .isEqualTo(answered.get(0).counterexample() + " (" + BehaviourJudge.BELOW_ONE_LEVEL + ")");
    }

    /**
     * On an input where two mistakes' models give the same colour, other than ours, an answer of
     * that colour is reproduced by each alone: neither is named, since naming one would lead with it.
     */
    @Test
    void twoEntriesThatEachGiveEveryAnswerAreNeitherNamed() {
        List<Variant> mistakes = java.util.stream.Stream.of(Variant.values())
                .filter(v -> v.method() == Variant.Method.ILLUMINATE && !v.isCorrect()).toList();
        BehaviourJudge.ShadeCase tie = null;
        for (BehaviourInputs.IlluminationCall call : BehaviourInputs.ILLUMINATIONS) {
            BehaviourJudge.ShadeCase asked = new BehaviourJudge.ShadeCase(call, null, Phong.FIXED);
            Vector3 ours = asked.model(BehaviourJudge.OURS);
            for (Variant first : mistakes) {
                Vector3 theirs = asked.model(java.util.EnumSet.of(first));
                boolean shared = mistakes.stream().filter(other -> other != first)
                        .anyMatch(other -> asked.model(java.util.EnumSet.of(other)).equals(theirs));
                if (tie == null && shared && !theirs.equals(ours)) {
                    tie = new BehaviourJudge.ShadeCase(call,
                            new Answers.Colour(new double[] {theirs.x, theirs.y, theirs.z}), Phong.FIXED);
                }
            }
        }
        assertThat(tie).as("an input where two mistakes give one colour that is not ours").isNotNull();

        assertThat(BehaviourJudge.reproducing(List.of(tie), Variant.Method.ILLUMINATE))
                .as("the entries named for an answer two of them give alone").isEmpty();
    }

    @Test
    void answersApartAtTheSeventhDigitAreStillPrintedShort() {
        assertThat(Words.colour(new Vector3(0.24, 0, 0.12))).as("a colour of short numbers")
                .isEqualTo("the colour (0.24, 0, 0.12)");
    }
}
