package gfx.tick1.command.shared.cli;

import picocli.CommandLine.Help.Ansi.Text;
import picocli.CommandLine.Help.Column;
import picocli.CommandLine.Help.ColorScheme;
import picocli.CommandLine.Help.TextTable;

/**
 * Picocli's text table, with a cell's text wrapped only at spaces. Picocli wraps with Java's line
 * BreakIterator, which also allows a break after a full stop, comma, colon, closing bracket and
 * more when a letter follows, and before an opening bracket: it splits {@code basic_scene.xml}
 * into {@code basic_scene.} and {@code xml} (picocli keeps only {@code -} whole). Here each such
 * character of an unstyled cell is handed to picocli as a character of Unicode's private use area,
 * which the BreakIterator takes for a letter, and given back when the table is printed; the rest
 * of picocli's layout (column widths, indents, the space at a line's end, over-long words) is
 * picocli's own.
 */
final class WholeTokenTable extends TextTable {

    /** ASCII punctuation {@code c} stands in a cell as {@code STAND_IN + c}, in the private use area. */
    private static final char STAND_IN = '\uE000';

    private final ColorScheme colorScheme;

    private WholeTokenTable(ColorScheme colorScheme, Column[] columns) {
        super(colorScheme, columns);
        this.colorScheme = colorScheme;
    }

    /** An empty table with the columns and settings of {@code table}, which picocli made for the same text. */
    static WholeTokenTable like(TextTable table, ColorScheme colorScheme) {
        WholeTokenTable whole = new WholeTokenTable(colorScheme, table.columns());
        whole.setAdjustLineBreaksForWideCJKCharacters(table.isAdjustLineBreaksForWideCJKCharacters());
        whole.indentWrappedLines = table.indentWrappedLines;
        return whole;
    }

    @Override
    public Cell putValue(int row, int col, Text value) {
        return super.putValue(row, col, value == null ? null : guarded(value));
    }

    /**
     * The text with its punctuation replaced by stand-ins. A styled text (an option's name in colour)
     * is left as it is, since the stand-ins would lose its style; picocli does not wrap those columns.
     */
    private Text guarded(Text value) {
        String plain = value.plainString();
        if (!value.toString().equals(plain)) {
            return value;
        }
        char[] chars = plain.toCharArray();
        for (int i = 0; i < chars.length; i++) {
            if (chars[i] > ' ' && chars[i] < 0x7F && !Character.isLetterOrDigit(chars[i])) {
                chars[i] = (char) (STAND_IN + chars[i]);
            }
        }
        return colorScheme.ansi().new Text(new String(chars), colorScheme);
    }

    @Override
    public StringBuilder toString(StringBuilder text) {
        int start = text.length();
        super.toString(text);
        for (int i = start; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c > STAND_IN + ' ' && c < STAND_IN + 0x7F) {
                text.setCharAt(i, (char) (c - STAND_IN));
            }
        }
        return text;
    }

    @Override
    public String toString() {
        return toString(new StringBuilder()).toString();
    }
}
