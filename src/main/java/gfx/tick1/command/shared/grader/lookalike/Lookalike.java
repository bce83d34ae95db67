package gfx.tick1.command.shared.grader.lookalike;

import gfx.tick1.command.shared.grader.model.Submission;
import java.util.List;

/**
 * Two submissions that look alike, or one that looks like tick1's reference, and why.
 *
 * @param a          the first submission
 * @param b          the second, or null for tick1's reference
 * @param similarity the share of both sides' tokens, the base's set aside, that lie in shared runs,
 *                   from 0 to 1: 2 x shared / (tokens of a + tokens of b)
 * @param reason     why the pair is listed
 * @param why        the reason in one short phrase, for a person
 * @param codeA      a's code as compared
 * @param codeB      b's code (or the reference's) as compared
 * @param tiles      the shared runs
 */
public record Lookalike(Submission a, Submission b, double similarity, Reason reason, String why,
        ComparedCode codeA, ComparedCode codeB, List<GreedyStringTiling.Tile> tiles) {

    /** Why a pair is listed, strongest evidence first. */
    public enum Reason {
        /** The two methods are tick1's reference's, in tokens after renaming. */
        REFERENCE,
        /** Most tokens lie in shared runs, after renaming and with the starter code set aside. */
        TOKENS,
        /** The same wrong answers, of a mistake no catalogue entry or probe names. */
        SAME_UNCATALOGUED_ANSWERS,
        /** The same wrong answers, of a mistake few in the cohort made. */
        SAME_WRONG_ANSWERS
    }

    public Lookalike {
        tiles = List.copyOf(tiles);
    }

    /** Whether B is tick1's reference rather than a student. */
    public boolean withReference() {
        return b == null;
    }

    /** For each token of a (true: b), whether it is in a shared run. */
    public boolean[] shared(boolean ofA) {
        boolean[] shared = new boolean[(ofA ? codeA : codeB).length()];
        for (GreedyStringTiling.Tile tile : tiles) {
            int start = ofA ? tile.a() : tile.b();
            java.util.Arrays.fill(shared, start, start + tile.length(), true);
        }
        return shared;
    }
}
