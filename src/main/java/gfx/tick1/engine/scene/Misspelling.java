package gfx.tick1.engine.scene;

import java.util.Collection;
import java.util.Comparator;
import java.util.Optional;

/**
 * The name a misspelt attribute most likely meant ({@code raduis}: radius, {@code color}: colour),
 * by the optimal string alignment distance: the fewest insertions, deletions, substitutions and
 * swaps of two neighbouring letters. A name counts as meant only within a third of its length,
 * so that a short name (x, y, z) is never offered for an unrelated word.
 */
public final class Misspelling {

    private Misspelling() {
    }

    /** The closest of {@code names} that {@code word} may be a misspelling of, if one is close. */
    static Optional<String> meant(String word, Collection<String> names) {
        return names.stream().filter(name -> !name.equals(word))
                .filter(name -> distance(word, name) <= name.length() / 3)
                .min(Comparator.comparingInt((String name) -> distance(word, name)).thenComparing(name -> name));
    }

    /** The optimal string alignment distance from {@code a} to {@code b}: each edit, or swap of neighbours, is one. */
    public static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= b.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(d[i - 1][j - 1] + cost, Math.min(d[i - 1][j], d[i][j - 1]) + 1);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }
}
