package gfx.tick1.scene;

import java.util.Arrays;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Line and column look-ups in a scene file's text, so that an error can point at the start of an
 * element or at the attribute that is wrong.
 *
 * <p>A SAX locator reports where a start tag <em>ends</em>; from there the tag's start is the
 * nearest '&lt;' before it, because XML forbids a raw '&lt;' inside attribute values.
 */
final class SourcePositions {

    /** A 1-based line and column, as editors and compilers print them. */
    record Position(int line, int column) implements Comparable<Position> {
        @Override
        public int compareTo(Position other) {
            return line != other.line ? Integer.compare(line, other.line) : Integer.compare(column, other.column);
        }

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

    /** The position of {@code name=} inside the tag that starts at {@code tag}, else the tag's. */
    Position attribute(Position tag, String name) {
        int start = offsetOf(tag.line(), tag.column());
        if (start < 0) {
            return tag;
        }
        int end = text.indexOf('>', start);
        String tagText = text.substring(start, end < 0 ? text.length() : end);
        Matcher m = Pattern.compile("\\s(" + Pattern.quote(name) + ")\\s*=").matcher(tagText);
        return m.find() ? positionOf(start + m.start(1)) : tag;
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
