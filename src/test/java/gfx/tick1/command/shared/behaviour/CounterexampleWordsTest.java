package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.harness.BehaviourInputs;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs.Phong;
import gfx.tick1.engine.math.Vector3;
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

    @Test
    void answersApartAtTheSeventhDigitAreStillPrintedShort() {
        assertThat(Words.colour(new Vector3(0.24, 0, 0.12))).as("a colour of short numbers")
                .isEqualTo("the colour (0.24, 0, 0.12)");
    }
}
