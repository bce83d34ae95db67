package gfx.tick1.command.diff;

import java.util.ArrayList;
import java.util.List;

/**
 * A line diff of two short texts, from their longest common subsequence of lines, as unified-diff
 * hunks: changed lines prefixed {@code -} (ours) and {@code +} (theirs), with up to
 * {@link #CONTEXT} unchanged lines around them prefixed by a space, in theirs' words.
 */
public final class LineDiff {

    /** Unchanged lines shown before and after each change, as {@code diff -u} shows. */
    private static final int CONTEXT = 3;

    /** One line of a hunk: ' ', '-' or '+', and its text. */
    public record Line(char kind, String text) {
    }

    private LineDiff() {
    }

    /** The hunks that turn {@code ours} into {@code theirs}; empty when they are the same. */
    public static List<List<Line>> hunks(List<String> ours, List<String> theirs) {
        return hunks(ours, ours, theirs, theirs);
    }

    /**
     * The hunks that turn {@code ours} into {@code theirs}. Two lines are kept when their keys (one
     * a line) are equal, or their texts are: a line written exactly as ours is never shown as
     * removed and added again, even where its key differs (a local declared earlier in theirs
     * numbers the locals after it otherwise). A kept line is shown as theirs, a removed one as
     * ours, an added one as theirs.
     */
    public static List<List<Line>> hunks(List<String> ours, List<String> ourKeys, List<String> theirs,
            List<String> theirKeys) {
        List<Line> all = edits(ours, ourKeys, theirs, theirKeys);
        List<List<Line>> hunks = new ArrayList<>();
        List<Line> hunk = null;
        int lastChange = Integer.MIN_VALUE;
        for (int i = 0; i < all.size(); i++) {
            if (all.get(i).kind() == ' ') {
                continue;
            }
            if (hunk == null || i - lastChange - 1 > 2 * CONTEXT) {
                if (hunk != null) {
                    closeHunk(hunk, all, lastChange);
                }
                hunk = new ArrayList<>(all.subList(Math.max(i - CONTEXT, 0), i));
                hunks.add(hunk);
            } else {
                hunk.addAll(all.subList(lastChange + 1, i));
            }
            hunk.add(all.get(i));
            lastChange = i;
        }
        if (hunk != null) {
            closeHunk(hunk, all, lastChange);
        }
        return hunks;
    }

    private static void closeHunk(List<Line> hunk, List<Line> all, int lastChange) {
        hunk.addAll(all.subList(lastChange + 1, Math.min(lastChange + 1 + CONTEXT, all.size())));
    }

    /** Every line of both texts, in order: kept, removed from ours, or added in theirs. */
    public static List<Line> edits(List<String> ours, List<String> theirs) {
        return edits(ours, ours, theirs, theirs);
    }

    private static List<Line> edits(List<String> ours, List<String> ourKeys, List<String> theirs,
            List<String> theirKeys) {
        int n = ours.size(), m = theirs.size();
        if (ourKeys.size() != n || theirKeys.size() != m) {
            throw new IllegalArgumentException("one key a line: " + ourKeys.size() + " keys for " + n + " lines, "
                    + theirKeys.size() + " for " + m);
        }
        int[][] common = new int[n + 1][m + 1]; // common[i][j]: LCS length of ours[i..] and theirs[j..]
        for (int i = n - 1; i >= 0; i--) {
            for (int j = m - 1; j >= 0; j--) {
                common[i][j] = kept(ours, ourKeys, i, theirs, theirKeys, j) ? common[i + 1][j + 1] + 1
                        : Math.max(common[i + 1][j], common[i][j + 1]);
            }
        }
        List<Line> lines = new ArrayList<>();
        int i = 0, j = 0;
        while (i < n || j < m) {
            if (i < n && j < m && kept(ours, ourKeys, i, theirs, theirKeys, j)) {
                lines.add(new Line(' ', theirs.get(j++)));
                i++;
            } else if (i < n && (j == m || common[i + 1][j] >= common[i][j + 1])) {
                lines.add(new Line('-', ours.get(i++)));
            } else {
                lines.add(new Line('+', theirs.get(j++)));
            }
        }
        return lines;
    }

    private static boolean kept(List<String> ours, List<String> ourKeys, int i, List<String> theirs,
            List<String> theirKeys, int j) {
        return ourKeys.get(i).equals(theirKeys.get(j)) || ours.get(i).equals(theirs.get(j));
    }
}
