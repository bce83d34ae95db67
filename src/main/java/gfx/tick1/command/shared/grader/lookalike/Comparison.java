package gfx.tick1.command.shared.grader.lookalike;

import java.util.Arrays;
import java.util.List;
import java.util.function.ToIntFunction;

/**
 * Two sides' code as compared, and the runs of tokens they share.
 *
 * @param codeA the first side's code
 * @param codeB the second side's code (or tick1's reference's)
 * @param tiles the shared runs
 */
public record Comparison(ComparedCode codeA, ComparedCode codeB, List<GreedyStringTiling.Tile> tiles) {

    public Comparison {
        tiles = List.copyOf(tiles);
    }

    /** The two sides' code and their shared runs, found by {@link GreedyStringTiling}. */
    static Comparison of(ComparedCode codeA, ComparedCode codeB) {
        return new Comparison(codeA, codeB, GreedyStringTiling.tiles(codeA.sequence, codeB.sequence));
    }

    /**
     * The share of both sides' tokens, the base's set aside, that lie in shared runs, from 0 to 1:
     * 2 x shared / (tokens of a + tokens of b).
     */
    public double similarity() {
        return Lookalikes.similarity(codeA, codeB, tiles);
    }

    /** For each token of a, whether it is in a shared run. */
    public boolean[] sharedOfA() {
        return shared(codeA.length(), GreedyStringTiling.Tile::a);
    }

    /** For each token of b, whether it is in a shared run. */
    public boolean[] sharedOfB() {
        return shared(codeB.length(), GreedyStringTiling.Tile::b);
    }

    private boolean[] shared(int length, ToIntFunction<GreedyStringTiling.Tile> start) {
        boolean[] shared = new boolean[length];
        for (GreedyStringTiling.Tile tile : tiles) {
            Arrays.fill(shared, start.applyAsInt(tile), start.applyAsInt(tile) + tile.length(), true);
        }
        return shared;
    }
}
