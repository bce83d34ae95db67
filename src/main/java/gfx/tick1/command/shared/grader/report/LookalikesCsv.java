package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.lookalike.Lookalike;
import gfx.tick1.command.shared.grader.lookalike.Lookalikes;
import gfx.tick1.command.shared.grader.model.Submission;
import java.util.List;

/**
 * {@code lookalikes.csv}: one row per pair of look-alikes, most similar first, with the students
 * named as Moodle's grading worksheet names them ({@code Participant <id>}), so that a row can be
 * found in the gradebook. UTF-8, CRLF, RFC 4180 quoting; no cell can become a formula.
 */
final class LookalikesCsv {

    /** The file in the report folder. */
    static final String NAME = "lookalikes.csv";
    static final List<String> HEADER = List.of("Identifier A", "Identifier B", "Similarity", "Why");

    private static final String PARTICIPANT = "Participant ";

    private LookalikesCsv() {
    }

    static String csv(List<Lookalike> pairs) {
        StringBuilder csv = new StringBuilder(64 + 96 * pairs.size());
        row(csv, HEADER);
        for (Lookalike pair : pairs) {
            row(csv, List.of(identifier(pair.a()), pair.b() == null ? Lookalikes.REFERENCE : identifier(pair.b()),
                    Lookalikes.percent(pair.similarity()), pair.why()));
        }
        return csv.toString();
    }

    /** "Participant 42", as the worksheet's Identifier column has it. */
    static String identifier(Submission submission) {
        return PARTICIPANT + submission.id();
    }

    private static void row(StringBuilder csv, List<String> cells) {
        for (int i = 0; i < cells.size(); i++) {
            csv.append(i == 0 ? "" : ",").append(CsvRecords.encode(CellText.cell(cells.get(i))));
        }
        csv.append("\r\n");
    }
}
