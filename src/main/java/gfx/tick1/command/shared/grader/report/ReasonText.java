package gfx.tick1.command.shared.grader.report;

import java.util.List;
import java.util.regex.Pattern;

/**
 * A reason as the feedback shows it: its prose, and the lines it quotes from javac as javac printed them. A compile
 * error's reason ends with the student's source line and a caret under the place of the error; collapsed into prose,
 * the caret would point nowhere, so from the source line on the lines are kept as they are.
 *
 * @param prose  the reason before any quoted lines, as one line of prose ({@link CellText#prose})
 * @param quoted the source line, the caret's line and any lines after them, unchanged; empty when there is no caret
 */
record ReasonText(String prose, List<String> quoted) {

    /** javac's caret line: spaces, then a {@code ^} under the column of the error. */
    private static final Pattern CARET = Pattern.compile("[ \\t]*\\^[ \\t]*");

    static ReasonText of(String reason) {
        List<String> lines = reason.lines().toList();
        for (int i = 2; i < lines.size(); i++) {
            if (CARET.matcher(lines.get(i)).matches()) {
                return new ReasonText(CellText.prose(String.join("\n", lines.subList(0, i - 1))),
                        lines.subList(i - 1, lines.size()).stream().map(String::stripTrailing).toList());
            }
        }
        return new ReasonText(CellText.prose(reason), List.of());
    }

    /**
     * The quoted lines as a {@code <pre>} and a line break, or nothing when there are none. The {@code <pre>} opens
     * with a line break, which HTML drops, so that each quoted line starts a line of the page.
     */
    String quotedHtml() {
        if (quoted.isEmpty()) {
            return "";
        }
        StringBuilder out = new StringBuilder("<pre class=\"quoted\">\n");
        quoted.forEach(line -> out.append(Html.escape(line)).append('\n'));
        return out.append("</pre>\n").toString();
    }
}
