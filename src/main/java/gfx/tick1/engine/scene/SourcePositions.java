package gfx.tick1.engine.scene;

import java.util.Arrays;

/**
 * Line and column look-ups in a scene file's text, so that an error can point at the start of an
 * element or at the attribute that is wrong.
 *
 * <p>A SAX locator reports where a start tag <em>ends</em>; from there the tag's start is the
 * nearest '&lt;' before it, because XML forbids a raw '&lt;' inside attribute values.
 */
final class SourcePositions {

    /** A 1-based line and column, as editors and compilers print them. */
    record Position(int line, int column) {
        @Override
        public String toString() {
            return line + ":" + column;
        }
    }

    private final String text;
    private final int[] lineStarts;

    SourcePositions(String text) {
        this.text = text;
        int[] starts = new int[16];
        int count = 0;
        starts[count++] = 0;
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                if (count == starts.length) {
                    starts = Arrays.copyOf(starts, count * 2);
                }
                starts[count++] = i + 1;
            }
        }
        this.lineStarts = Arrays.copyOf(starts, count);
    }

    /** The position of the '&lt;' of the start tag whose end the locator reported. */
    Position tagStart(int locatorLine, int locatorColumn) {
        int end = offsetOf(locatorLine, locatorColumn);
        if (end < 0) {
            return new Position(locatorLine, locatorColumn);
        }
        int start = text.lastIndexOf('<', Math.max(0, end - 1));
        return start < 0 ? new Position(locatorLine, locatorColumn) : positionOf(start);
    }

    /**
     * The position of {@code name=} inside the start tag that begins at {@code tag}, else the
     * tag's. The tag is read as XML defines it: its name, then name="value" or name='value' pairs,
     * so that a '&gt;' or a name inside a quoted value is passed over.
     */
    Position attribute(Position tag, String name) {
        int i = offsetOf(tag.line(), tag.column());
        if (i < 0 || i >= text.length() || text.charAt(i) != '<') {
            return tag;
        }
        i = skipName(i + 1);
        while (true) {
            i = skipSpace(i);
            int nameStart = i;
            i = skipName(i);
            if (i == nameStart) {
                return tag; // '>' or '/>': the end of the tag, and no such attribute
            }
            if (text.regionMatches(nameStart, name, 0, name.length()) && i - nameStart == name.length()) {
                return positionOf(nameStart);
            }
            i = skipSpace(i);
            if (i >= text.length() || text.charAt(i) != '=') {
                return tag;
            }
            i = skipSpace(i + 1);
            if (i >= text.length() || (text.charAt(i) != '"' && text.charAt(i) != '\'')) {
                return tag;
            }
            int close = text.indexOf(text.charAt(i), i + 1);
            if (close < 0) {
                return tag;
            }
            i = close + 1;
        }
    }

    private int skipSpace(int i) {
        while (i < text.length() && Character.isWhitespace(text.charAt(i))) {
            i++;
        }
        return i;
    }

    /** Past an XML name: everything up to white space, '=', '/', '&gt;' or a quote. */
    private int skipName(int i) {
        while (i < text.length() && "=/>\"'".indexOf(text.charAt(i)) < 0 && !Character.isWhitespace(text.charAt(i))) {
            i++;
        }
        return i;
    }

    private int offsetOf(int line, int column) {
        if (line < 1 || line > lineStarts.length || column < 1) {
            return -1;
        }
        int offset = lineStarts[line - 1] + column - 1;
        return offset <= text.length() ? offset : -1;
    }

    private Position positionOf(int offset) {
        int index = Arrays.binarySearch(lineStarts, offset);
        int line = index >= 0 ? index : -index - 2;
        return new Position(line + 1, offset - lineStarts[line] + 1);
    }
}
