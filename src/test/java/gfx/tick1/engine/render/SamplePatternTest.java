package gfx.tick1.engine.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

class SamplePatternTest {

    @Test
    void theFirstSampleIsThePixelCentreSoOneSampleIsTheFaithfulImage() {
        SamplePattern one = new SamplePattern(1);
        assertThat(one.dx(0)).isZero();
        assertThat(one.dy(0)).isZero();
    }

    @Test
    void everyOffsetLiesInsideThePixel() {
        SamplePattern pattern = new SamplePattern(SamplePattern.MAX_SAMPLES);
        for (int i = 0; i < pattern.size(); i++) {
            assertThat(pattern.dx(i)).isBetween(-0.5, 0.5).isNotEqualTo(0.5);
            assertThat(pattern.dy(i)).isBetween(-0.5, 0.5).isNotEqualTo(0.5);
        }
    }

    @Test
    void samplesAreSpreadOverEveryQuarterOfThePixel() {
        SamplePattern pattern = new SamplePattern(16);
        int[] quadrants = new int[4];
        Set<Double> distinct = new HashSet<>();
        for (int i = 0; i < pattern.size(); i++) {
            quadrants[(pattern.dx(i) < 0 ? 0 : 1) + (pattern.dy(i) < 0 ? 0 : 2)]++;
            distinct.add(pattern.dx(i) * 1000 + pattern.dy(i));
        }
        assertThat(distinct).hasSize(16);
        for (int quadrant : quadrants) {
            assertThat(quadrant).as("samples per quarter of the pixel").isBetween(3, 5);
        }
    }

    @Test
    void sampleCountsOutsideTheRangeAreRefused() {
        assertThatThrownBy(() -> new SamplePattern(0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new SamplePattern(SamplePattern.MAX_SAMPLES + 1))
                .isInstanceOf(IllegalArgumentException.class);
    }
}
