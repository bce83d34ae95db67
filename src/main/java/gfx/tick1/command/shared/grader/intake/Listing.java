package gfx.tick1.command.shared.grader.intake;

import java.util.List;
import java.util.Locale;

/**
 * Lists of names for a reason, bounded: a reason is read by a person and stored in every page
 * and cell of the report, so however many files a student's archive holds, a list shows a few of
 * them and counts the rest ("a, b, c and 19,997 more").
 */
final class Listing {

    /** How many names a list shows. */
    static final int SHOWN = 3;
    /** The most characters of one name shown. */
    static final int MAX_NAME = 120;

    private Listing() {
    }

    /** "a", "a and b", "a, b and c", or "a, b, c and 19,997 more". */
    static String some(List<String> names) {
        List<String> shown = names.stream().limit(SHOWN).map(Listing::bounded).toList();
        int rest = names.size() - shown.size();
        if (rest > 0) {
            return String.join(", ", shown) + String.format(Locale.ROOT, " and %,d more", rest);
        }
        if (shown.size() == 1) {
            return shown.get(0);
        }
        return String.join(", ", shown.subList(0, shown.size() - 1)) + " and " + shown.get(shown.size() - 1);
    }

    /** "two files", "20,000 files": a count of at least two, in words where it is two. */
    static String count(int count, String noun) {
        return (count == 2 ? "two" : String.format(Locale.ROOT, "%,d", count)) + " " + noun + "s";
    }

    private static String bounded(String name) {
        return name.length() <= MAX_NAME ? name : name.substring(0, MAX_NAME - 1) + "\u2026";
    }
}
