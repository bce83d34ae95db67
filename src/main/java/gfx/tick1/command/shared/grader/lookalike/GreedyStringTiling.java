package gfx.tick1.command.shared.grader.lookalike;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;

/**
 * Greedy String Tiling (Wise, "Neweyes: a system for comparing biological sequences using the
 * running Karp-Rabin greedy string-tiling algorithm", 1993; the algorithm JPlag uses): the most
 * tokens two sequences can be covered with by common runs ("tiles") of at least a minimum length,
 * taken longest first, each token in at most one tile. A run moved, duplicated or interleaved with
 * new code is still found, which a longest-common-subsequence would miss.
 *
 * <p>The candidate starts of each round are the pairs of positions whose next {@code minimum}
 * tokens hash alike (Karp-Rabin's idea), found once per pair of sequences by merging their sorted
 * hashes, instead of every pair of positions; a start is extended only where the run does not
 * extend backwards, so a long common run costs its length, not its square.
 */
final class GreedyStringTiling {

    /** A common run: where it starts in each sequence, and its length in tokens. */
    record Tile(int a, int b, int length) {
    }

    /**
     * A sequence of tokens prepared for tiling: its tokens, those set aside (the base code's: never
     * part of a tile), and the hashes of its runs of {@code minimum} tokens with none set aside,
     * sorted, with where each starts. A run of tokens that repeats more than {@link #MOST_REPEATS}
     * times is indexed at its first places only, so that hostile repetitive code costs no more than
     * honest code.
     */
    static final class Sequence {
        /** The most places one run of {@code minimum} tokens is indexed at. */
        static final int MOST_REPEATS = 16;

        final int[] tokens;
        final boolean[] setAside;
        final int minimum;
        final long[] hashes;
        final int[] starts;

        Sequence(int[] tokens, boolean[] setAside, int minimum) {
            this.tokens = tokens;
            this.setAside = setAside;
            this.minimum = minimum;
            long[][] grams = grams(tokens, setAside, minimum);
            Arrays.sort(grams, (x, y) -> x[0] != y[0] ? Long.compare(x[0], y[0]) : Long.compare(x[1], y[1]));
            List<long[]> kept = new ArrayList<>();
            int repeats = 0;
            for (int i = 0; i < grams.length; i++) {
                repeats = i > 0 && grams[i][0] == grams[i - 1][0] ? repeats + 1 : 0;
                if (repeats < MOST_REPEATS) {
                    kept.add(grams[i]);
                }
            }
            hashes = kept.stream().mapToLong(gram -> gram[0]).toArray();
            starts = kept.stream().mapToInt(gram -> (int) gram[1]).toArray();
        }

        /** How many tokens are not set aside. */
        int counted() {
            int counted = 0;
            for (boolean aside : setAside) {
                counted += aside ? 0 : 1;
            }
            return counted;
        }

        /** Each run of {@code minimum} tokens with none set aside: {hash, start}. */
        private static long[][] grams(int[] tokens, boolean[] setAside, int minimum) {
            List<long[]> grams = new ArrayList<>();
            for (int start = 0; start + minimum <= tokens.length; start++) {
                long hash = 1;
                boolean clear = true;
                for (int k = 0; k < minimum && clear; k++) {
                    clear = !setAside[start + k];
                    hash = hash * 1_000_003L + tokens[start + k];
                }
                if (clear) {
                    grams.add(new long[] {hash, start});
                }
            }
            return grams.toArray(new long[0][]);
        }
    }

    private GreedyStringTiling() {
    }

    /** The tiles of {@code a} and {@code b} (prepared with the same minimum), longest first. */
    static List<Tile> tiles(Sequence a, Sequence b) {
        int minimum = a.minimum;
        if (b.minimum != minimum) {
            throw new IllegalArgumentException("sequences prepared for different minimum lengths");
        }
        int[] candidates = candidates(a, b);
        boolean[] markedA = a.setAside.clone();
        boolean[] markedB = b.setAside.clone();
        List<Tile> tiles = new ArrayList<>();
        int longest;
        do {
            longest = minimum;
            List<Tile> matches = new ArrayList<>();
            for (int c = 0; c < candidates.length; c += 2) {
                int i = candidates[c];
                int j = candidates[c + 1];
                if (markedA[i] || markedB[j] || i > 0 && j > 0 && !markedA[i - 1] && !markedB[j - 1]
                        && a.tokens[i - 1] == b.tokens[j - 1]) {
                    continue;
                }
                int length = 0;
                while (i + length < a.tokens.length && j + length < b.tokens.length && !markedA[i + length]
                        && !markedB[j + length] && a.tokens[i + length] == b.tokens[j + length]) {
                    length++;
                }
                if (length > longest) {
                    matches.clear();
                    longest = length;
                }
                if (length == longest) {
                    matches.add(new Tile(i, j, length));
                }
            }
            // Candidates come in the order of their runs' hashes, which depend on how the tokens were numbered (the
            // order files were read in): of two equal runs that overlap, the one that starts first is the tile.
            matches.sort(Comparator.comparingInt(Tile::a).thenComparingInt(Tile::b));
            for (Tile match : matches) {
                if (unmarked(markedA, match.a(), match.length()) && unmarked(markedB, match.b(), match.length())) {
                    Arrays.fill(markedA, match.a(), match.a() + match.length(), true);
                    Arrays.fill(markedB, match.b(), match.b() + match.length(), true);
                    tiles.add(match);
                }
            }
        } while (longest > minimum);
        return tiles;
    }

    /** The pairs of starts whose runs hash alike, as i, j, i, j, ...: a merge of the two sorted hash lists. */
    private static int[] candidates(Sequence a, Sequence b) {
        int[] pairs = new int[16];
        int count = 0;
        int i = 0;
        int j = 0;
        while (i < a.hashes.length && j < b.hashes.length) {
            if (a.hashes[i] < b.hashes[j]) {
                i++;
            } else if (a.hashes[i] > b.hashes[j]) {
                j++;
            } else {
                int iEnd = i;
                int jEnd = j;
                while (iEnd < a.hashes.length && a.hashes[iEnd] == a.hashes[i]) {
                    iEnd++;
                }
                while (jEnd < b.hashes.length && b.hashes[jEnd] == b.hashes[j]) {
                    jEnd++;
                }
                for (int x = i; x < iEnd; x++) {
                    for (int y = j; y < jEnd; y++) {
                        if (count + 2 > pairs.length) {
                            pairs = Arrays.copyOf(pairs, pairs.length * 2);
                        }
                        pairs[count++] = a.starts[x];
                        pairs[count++] = b.starts[y];
                    }
                }
                i = iEnd;
                j = jEnd;
            }
        }
        return Arrays.copyOf(pairs, count);
    }

    private static boolean unmarked(boolean[] marked, int from, int length) {
        for (int k = from; k < from + length; k++) {
            if (marked[k]) {
                return false;
            }
        }
        return true;
    }
}
