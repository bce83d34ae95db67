package gfx.tick1.command.diff;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The hunks of {@code tick1 diff}: which lines are kept, and in whose words they are shown. */
class LineDiffTest {

    @Test
    void aKeptLineIsShownInTheirWordsWhereOnlyItsKeyIsOurs() {
        List<LineDiff.Line> edits = LineDiff.hunks(List.of("double x = a;", "return x;"), List.of("#1 = a", "ret #1"),
                List.of("final double y = a;", "return y + 1;"), List.of("#1 = a", "ret #1 + 1")).get(0);
        assertThat(edits).as("the first line kept, in their words; the second changed")
                .containsExactly(new LineDiff.Line(' ', "final double y = a;"), new LineDiff.Line('-', "return x;"),
                        new LineDiff.Line('+', "return y + 1;"));
    }

    /** A local declared earlier in theirs numbers every later one otherwise: the text still matches. */
    @Test
    void aLineWrittenExactlyAsOursIsKeptWhateverItsKey() {
        List<LineDiff.Line> edits = LineDiff.hunks(List.of("double s = t;", "return s;"), List.of("#1 = t", "ret #1"),
                List.of("double u = 0;", "double s = t;", "return s;"), List.of("#1 = 0", "#2 = t", "ret #2")).get(0);
        assertThat(edits).as("only the new line differs")
                .containsExactly(new LineDiff.Line('+', "double u = 0;"), new LineDiff.Line(' ', "double s = t;"),
                        new LineDiff.Line(' ', "return s;"));
    }

    @Test
    void linesThatDifferInTextAndKeyAreRemovedAndAdded() {
        assertThat(LineDiff.hunks(List.of("a"), List.of("1"), List.of("b"), List.of("2")).get(0))
                .as("a real change").containsExactly(new LineDiff.Line('-', "a"), new LineDiff.Line('+', "b"));
    }
}
