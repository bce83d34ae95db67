package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The labelled ticks of the plot's time axis: enough to read a time off, never crowded. */
class LogTicksTest {

    @Test
    void everyAxisOfAtLeastAFactorOfFourHasThreeToTwelveLabelsInsideIt() {
        SplittableRandom random = new SplittableRandom(4);
        for (int i = 0; i < 20_000; i++) {
            double min = Math.pow(10, random.nextDouble(-2, 6));
            double max = min * Math.pow(10, random.nextDouble(Math.log10(4), 4));
            List<Double> labelled = new LogTicks(min, max).labelled();
            assertThat(labelled).as("%s to %s ms", min, max).hasSizeBetween(3, 12)
                    .allSatisfy(value -> assertThat(value).isBetween(min, max)).isSorted();
        }
    }

    @Test
    void aRangeOfAFewDecadesIsLabelledInOneTwoFiveSteps() {
        assertThat(new LogTicks(6, 130).labelled()).containsExactly(10.0, 20.0, 50.0, 100.0);
        assertThat(new LogTicks(0.4, 30).labelled()).containsExactly(0.5, 1.0, 2.0, 5.0, 10.0, 20.0);
    }

    @Test
    void aNarrowRangeIsLabelledInOneTwoThreeFiveSteps() {
        assertThat(new LogTicks(108, 720).labelled()).containsExactly(200.0, 300.0, 500.0);
    }

    @Test
    void aRangeTooNarrowForThoseIsLabelledAtEveryTick() {
        assertThat(new LogTicks(510, 2040).labelled()).containsExactly(600.0, 700.0, 800.0, 900.0, 1000.0, 2000.0);
    }

    @Test
    void aWideRangeIsLabelledAtThePowersOfTenOnly() {
        assertThat(new LogTicks(0.5, 20_000).labelled()).containsExactly(1.0, 10.0, 100.0, 1000.0, 10_000.0);
    }

    @Test
    void labelsReadAsAPersonWritesNumbers() {
        assertThat(LogTicks.text(0.5)).isEqualTo("0.5");
        assertThat(LogTicks.text(0.3)).isEqualTo("0.3");
        assertThat(LogTicks.text(20)).isEqualTo("20");
        assertThat(LogTicks.text(10_000)).isEqualTo("10,000");
    }
}
