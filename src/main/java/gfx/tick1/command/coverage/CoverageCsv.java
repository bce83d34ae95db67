package gfx.tick1.command.coverage;

import gfx.tick1.command.shared.coverage.Caught;
import gfx.tick1.command.shared.coverage.Coverage;
import java.util.ArrayList;
import java.util.List;

/**
 * A {@link Coverage} as CSV (RFC 4180): the header {@code Mistake,Scene,Pixels differing}, then
 * one row per mistake and scene, then the same for each pair, named as {@code grade} names two
 * mistakes together.
 */
final class CoverageCsv {

    static final String HEADER = "Mistake,Scene,Pixels differing";

    private CoverageCsv() {
    }

    static String of(Coverage coverage) {
        List<Caught> rows = new ArrayList<>(coverage.mistakes());
        rows.addAll(coverage.pairs());
        StringBuilder csv = new StringBuilder(HEADER).append("\r\n");
        for (Caught row : rows) {
            for (int i = 0; i < coverage.scenes().size(); i++) {
                csv.append(cell(row.title())).append(',').append(cell(coverage.scenes().get(i))).append(',')
                        .append(row.pixels().get(i)).append("\r\n");
            }
        }
        return csv.toString();
    }

    /** A cell, between quotes (a quote doubled) when it holds a comma, a quote or a line break. */
    private static String cell(String text) {
        boolean quoted = text.chars().anyMatch(c -> c == ',' || c == '"' || c == '\r' || c == '\n');
        return quoted ? '"' + text.replace("\"", "\"\"") + '"' : text;
    }
}
