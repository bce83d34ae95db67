package gfx.tick1.engine.io;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Counts agree with their nouns in number. */
class CountedTest {

    @ParameterizedTest(name = "{0} {1}: {2}")
    @CsvSource({"0, pixel, 0 pixels", "1, pixel, 1 pixel", "2, pixel, 2 pixels", "1, level, 1 level",
        "15350, pixel, 15350 pixels"})
    void aCountOfOneTakesTheSingularAndAnyOtherThePlural(long count, String noun, String expected) {
        assertThat(Counted.of(count, noun)).as("%d %s", count, noun).isEqualTo(expected);
    }
}
