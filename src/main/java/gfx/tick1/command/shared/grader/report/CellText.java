package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.FindingText;

/**
 * Text made fit for a cell tick1 writes into a worksheet, and for the one-line reason a page shows.
 * Names and reasons come from students' archives and their code's output, so each is bounded, and
 * none can become a formula in the spreadsheet that opens the worksheet.
 */
final class CellText {

    /** The most characters of a cell: more than a reason the report keeps, escaped; a real name is far shorter. */
    static final int MAX_CELL = 3_000;

    /** The most characters of a reason in a short column (the cohort page's Reason). */
    static final int MAX_SHORT = 160;

    private static final String ELLIPSIS = "\u2026";

    private CellText() {
    }

    /**
     * A cell's text, at most {@link #MAX_CELL} characters, with a leading {@code '} where it starts
     * as a spreadsheet formula does ({@code = + - @}, a tab or a carriage return), as Moodle's own
     * export writes such a cell: the spreadsheet then shows the text instead of running it.
     */
    static String cell(String text) {
        String bounded = bounded(text, MAX_CELL);
        return !bounded.isEmpty() && "=+-@\t\r".indexOf(bounded.charAt(0)) >= 0 ? "'" + bounded : bounded;
    }

    /**
     * A feedback comment for Moodle, which stores that column as HTML: plain text with {@code &},
     * {@code <} and {@code >} written as references, so that what a zip path or an exception held
     * shows as text; a line break becomes a space (HTML shows one as a space anyway), and the
     * terminal's padding of figures ({@code ( 67.838%}) goes, as do the source line and caret a compile error quotes
     * (whose columns a comment cannot keep). Then bounded, between two findings ({@link FindingText}),
     * and escaped as {@link #cell}.
     */
    static String comment(String reason) {
        String prose = ReasonText.of(reason).prose().replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
        return cell(FindingText.fitted(prose, MAX_CELL - 1, CohortOutputs.REST));
    }

    /** A reason as one line of prose: runs of white space (line breaks included) as one space, no "( " padding. */
    static String prose(String reason) {
        return reason.replaceAll("\\s+", " ").replace("( ", "(").strip();
    }

    /** A reason for a short column: its prose, cut at a word near {@link #MAX_SHORT} characters with an ellipsis. */
    static String shortReason(String reason) {
        String prose = prose(reason);
        if (prose.length() <= MAX_SHORT) {
            return prose;
        }
        int cut = prose.lastIndexOf(' ', MAX_SHORT - 1);
        return prose.substring(0, cut > MAX_SHORT / 2 ? cut : MAX_SHORT - 1) + ELLIPSIS;
    }

    /** {@code text} (null too), or its first {@code most - 1} characters and an ellipsis; a surrogate pair is kept. */
    static String bounded(String text, int most) {
        if (text == null || text.length() <= most) {
            return text;
        }
        int end = most - 1;
        if (Character.isHighSurrogate(text.charAt(end - 1))) {
            end--;
        }
        return text.substring(0, end) + ELLIPSIS;
    }
}
