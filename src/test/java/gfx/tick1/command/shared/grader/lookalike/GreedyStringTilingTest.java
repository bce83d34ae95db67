package gfx.tick1.command.shared.grader.lookalike;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.lookalike.GreedyStringTiling.Tile;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Greedy String Tiling on small sequences whose tiles can be worked out by hand. */
class GreedyStringTilingTest {

    private static GreedyStringTiling.Sequence sequence(int minimum, int... tokens) {
        return new GreedyStringTiling.Sequence(tokens, new boolean[tokens.length], minimum);
    }

    @Test
    void twoBlocksInTheOtherOrderAreEachATile() {
        List<Tile> tiles = GreedyStringTiling.tiles(sequence(3, 1, 2, 3, 4, 9, 5, 6, 7),
                sequence(3, 5, 6, 7, 8, 1, 2, 3, 4));
        assertThat(tiles).as("the tiles of two blocks swapped, the longer first")
                .containsExactly(new Tile(0, 4, 4), new Tile(5, 0, 3));
    }

    @Test
    void aCommonRunShorterThanTheMinimumIsNoTile() {
        assertThat(GreedyStringTiling.tiles(sequence(4, 1, 2, 3, 9), sequence(4, 8, 1, 2, 3)))
                .as("a run of 3 with a minimum of 4").isEmpty();
    }

    @Test
    void eachTokenIsInOneTileAtMost() {
        List<Tile> tiles = GreedyStringTiling.tiles(sequence(2, 1, 2, 1, 2), sequence(2, 1, 2));
        assertThat(tiles).as("one copy of a run that the other side holds once").containsExactly(new Tile(0, 0, 2));
    }

    @Test
    void tokensSetAsideAreInNoTile() {
        boolean[] aside = {true, true, false, false, false};
        GreedyStringTiling.Sequence withBase = new GreedyStringTiling.Sequence(new int[] {1, 2, 3, 4, 5}, aside, 2);
        List<Tile> tiles = GreedyStringTiling.tiles(withBase, sequence(2, 1, 2, 3, 4, 5));
        assertThat(tiles).as("the tiles when the first two tokens are the base's").containsExactly(new Tile(2, 2, 3));
    }

    @Test
    void ofTwoEqualRunsThatOverlapTheEarlierIsTheTileHoweverTheTokensAreNumbered() {
        // [1 2] and [2 3] are both common runs of two; they share the 2 of the first sequence, so only one is a tile.
        // Token numbers follow the order in which files were read, which varies: renumbering must change nothing.
        List<Tile> numbered = GreedyStringTiling.tiles(sequence(2, 1, 2, 3), sequence(2, 1, 2, 5, 2, 3));
        List<Tile> renumbered = GreedyStringTiling.tiles(sequence(2, 3, 2, 1), sequence(2, 3, 2, 5, 2, 1));
        assertThat(numbered).as("the tile of the run that starts first").containsExactly(new Tile(0, 0, 2));
        assertThat(renumbered).as("the same tokens numbered the other way round").isEqualTo(numbered);
    }
}
