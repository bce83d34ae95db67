package gfx.tick1.command.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.coverage.Caught;
import gfx.tick1.command.shared.coverage.Coverage;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The console's report of a {@link Coverage}: the table of pixels, then what each scene alone catches
 * and what none does.
 */
final class CoverageTable {

    private CoverageTable() {
    }

    static List<String> lines(Coverage coverage) {
        List<String> lines = new ArrayList<>();
        lines.add("Pixels differing from the image a pass needs, at " + coverage.width() + " x " + coverage.height()
                + " (0: the scene does not catch the mistake):");
        List<String> header = new ArrayList<>(List.of("mistake"));
        coverage.scenes().forEach(scene -> header.add(plain(scene)));
        header.add("all");
        List<List<String>> rows = new ArrayList<>(List.of(header));
        coverage.mistakes().forEach(mistake -> rows.add(row(mistake)));
        lines.addAll(aligned(rows));
        lines.add("");
        for (int i = 0; i < coverage.scenes().size(); i++) {
            lines.add("Caught by " + plain(coverage.scenes().get(i)) + " alone: " + titles(coverage.caughtOnlyBy(i)));
        }
        List<Variant> missed = coverage.missed();
        lines.add("Caught by no scene: " + (missed.isEmpty() ? "none" : missed.size() + ""));
        for (Variant mistake : missed) {
            lines.add("  " + mistake.title()
                    + coverage.reason(mistake).map(reason -> ": " + reason.words()).orElse(""));
        }
        for (int i = 0; i < coverage.scenes().size(); i++) {
            if (coverage.sixSteps().caughtBy(i)) {
                lines.add("Warning: " + plain(coverage.scenes().get(i)) + " fails a correct answer: the handout's six "
                        + "steps taken literally differ on " + number(coverage.sixSteps().pixels().get(i)) + " pixels "
                        + "(a ray starts inside a sphere or on its surface, or grazes one)");
            }
        }
        if (!coverage.pairs().isEmpty()) {
            lines.add("");
            lines.add("Pairs that tick1 names together, where some scene catches neither mistake alone:");
            for (Caught pair : coverage.pairs()) {
                List<String> counts = new ArrayList<>();
                for (int i = 0; i < coverage.scenes().size(); i++) {
                    counts.add(plain(coverage.scenes().get(i)) + " " + number(pair.pixels().get(i)));
                }
                lines.add("  " + pair.title() + ": " + String.join(", ", counts)
                        + (pair.caught() ? "" : "; caught by no scene"));
            }
        }
        return lines;
    }

    private static List<String> row(Caught mistake) {
        List<String> row = new ArrayList<>(List.of(mistake.title()));
        mistake.pixels().forEach(pixels -> row.add(number(pixels)));
        row.add(number(mistake.total()));
        return row;
    }

    /** The first column left-aligned, the numbers right-aligned, two spaces apart. */
    private static List<String> aligned(List<List<String>> rows) {
        int columns = rows.get(0).size();
        int[] widths = new int[columns];
        rows.forEach(row -> {
            for (int c = 0; c < columns; c++) {
                widths[c] = Math.max(widths[c], row.get(c).length());
            }
        });
        List<String> lines = new ArrayList<>();
        for (List<String> row : rows) {
            StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "%-" + widths[0] + "s", row.get(0)));
            for (int c = 1; c < columns; c++) {
                line.append(String.format(Locale.ROOT, "  %" + widths[c] + "s", row.get(c)));
            }
            lines.add(line.toString().stripTrailing());
        }
        return lines;
    }

    /**
     * A scene's name for a terminal: control characters, which a terminal would obey, and the
     * bidirectional formatting characters, which can make a line read as another, as U+FFFD.
     */
    static String plain(String name) {
        return name.replaceAll("[\\p{Cc}\u202A-\u202E\u2066-\u2069]", "\uFFFD");
    }

    static String number(long value) {
        return String.format(Locale.ROOT, "%,d", value);
    }

    private static String titles(List<Variant> mistakes) {
        return mistakes.isEmpty() ? "none" : String.join("; ", mistakes.stream().map(Variant::title).toList());
    }
}
