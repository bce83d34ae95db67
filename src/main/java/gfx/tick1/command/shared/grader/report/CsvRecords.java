package gfx.tick1.command.shared.grader.report;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * A CSV file (RFC 4180) read as records of cells that remember where their bytes lie, so that a few cells can be
 * replaced and every other byte (quoting, line endings, a byte-order mark) kept as it was.
 *
 * <p>Read as RFC 4180 says, and as spreadsheets write it: a cell that starts with {@code "} runs to the next lone
 * {@code "} ({@code ""} inside is one quote) and may hold commas and line breaks; any other cell runs to the next
 * comma or line break, quotes and all. A record ends at CRLF, LF or a lone CR; the last may have none.
 */
final class CsvRecords {

    private static final byte QUOTE = '"';
    private static final byte COMMA = ',';
    private static final byte CR = '\r';
    private static final byte LF = '\n';
    private static final byte[] BOM = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};

    /** A file that is not CSV: the line it happened on, and what was wrong. */
    static final class Malformed extends Exception {
        private static final long serialVersionUID = 1L;
        final int line;

        Malformed(int line, String message) {
            super(message);
            this.line = line;
        }
    }

    /**
     * One cell.
     *
     * @param start  where its bytes start, the opening quote included
     * @param end    where they end, the closing quote included
     * @param quoted it was written between quotes
     * @param value  its text, quotes removed and {@code ""} read as {@code "}
     */
    record Cell(int start, int end, boolean quoted, String value) {
    }

    /**
     * One record.
     *
     * @param line  the line it starts on, from 1
     * @param cells its cells, in order
     */
    record Row(int line, List<Cell> cells) {

        /** The value of the cell at this index, or "" where the row is shorter. */
        String value(int index) {
            return index < cells.size() ? cells.get(index).value() : "";
        }

        /** The values of its cells, in order. */
        List<String> values() {
            return cells.stream().map(Cell::value).toList();
        }

        /** A line on its own: one empty cell. */
        boolean blank() {
            return cells.size() == 1 && cells.get(0).end() == cells.get(0).start();
        }
    }

    private CsvRecords() {
    }

    /** The length of a UTF-8 byte-order mark at the start, or 0. */
    static int bomLength(byte[] bytes) {
        return bytes.length >= 3 && bytes[0] == BOM[0] && bytes[1] == BOM[1] && bytes[2] == BOM[2] ? 3 : 0;
    }

    /** The file's records, after a byte-order mark; {@link Malformed} when it is not UTF-8 or not CSV. */
    static List<Row> read(byte[] bytes) throws Malformed {
        checkUtf8(bytes);
        List<Row> rows = new ArrayList<>();
        int at = bomLength(bytes);
        int line = 1;
        while (at < bytes.length) {
            int start = at;
            List<Cell> cells = new ArrayList<>();
            while (true) {
                int cellStart = at;
                boolean quoted = at < bytes.length && bytes[at] == QUOTE;
                if (quoted) {
                    at = closingQuote(bytes, at, line + breaks(bytes, start, cellStart));
                    if (at < bytes.length && bytes[at] != COMMA && bytes[at] != CR && bytes[at] != LF) {
                        throw new Malformed(line + breaks(bytes, start, at), "text after a closing quote in a cell "
                                + "(a quote inside a quoted cell is written \"\")");
                    }
                } else {
                    while (at < bytes.length && bytes[at] != COMMA && bytes[at] != CR && bytes[at] != LF) {
                        at++;
                    }
                }
                cells.add(new Cell(cellStart, at, quoted, value(bytes, cellStart, at, quoted)));
                if (at < bytes.length && bytes[at] == COMMA) {
                    at++;
                    continue;
                }
                at += at + 1 < bytes.length && bytes[at] == CR && bytes[at + 1] == LF ? 2 : at < bytes.length ? 1 : 0;
                break;
            }
            rows.add(new Row(line, List.copyOf(cells)));
            line += breaks(bytes, start, at);
        }
        return rows;
    }

    /** The index just after the quote that closes the cell opened at {@code open}. */
    private static int closingQuote(byte[] bytes, int open, int line) throws Malformed {
        int at = open + 1;
        while (true) {
            if (at >= bytes.length) {
                throw new Malformed(line, "a quoted cell is never closed (a \" with no closing \")");
            }
            if (bytes[at] == QUOTE) {
                if (at + 1 < bytes.length && bytes[at + 1] == QUOTE) {
                    at += 2;
                    continue;
                }
                return at + 1;
            }
            at++;
        }
    }

    private static String value(byte[] bytes, int start, int end, boolean quoted) {
        if (!quoted) {
            return new String(bytes, start, end - start, StandardCharsets.UTF_8);
        }
        return new String(bytes, start + 1, end - start - 2, StandardCharsets.UTF_8).replace("\"\"", "\"");
    }

    /** Line breaks (CRLF, LF or a lone CR) in {@code [from, to)}. */
    private static int breaks(byte[] bytes, int from, int to) {
        int count = 0;
        for (int i = from; i < to; i++) {
            if (bytes[i] == LF || bytes[i] == CR && (i + 1 >= bytes.length || bytes[i + 1] != LF)) {
                count++;
            }
        }
        return count;
    }

    private static void checkUtf8(byte[] bytes) throws Malformed {
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(8192);
        while (true) {
            CoderResult result = decoder.decode(in, out, true);
            if (result.isError()) {
                throw new Malformed(1 + breaks(bytes, 0, in.position()), "byte 0x" + String.format("%02X",
                        bytes[in.position()] & 0xFF) + " is not UTF-8 (save the worksheet as \"CSV UTF-8\")");
            }
            if (result.isUnderflow()) {
                return;
            }
            out.clear();
        }
    }

    /** A cell's text as RFC 4180 writes it: between quotes when it holds a comma, quote or break. */
    static String encode(String value) {
        boolean needed = value.indexOf(',') >= 0 || value.indexOf('"') >= 0 || value.indexOf('\r') >= 0
                || value.indexOf('\n') >= 0;
        return needed ? quoted(value) : value;
    }

    /** A cell's text between quotes, as RFC 4180 writes it. */
    static String quoted(String value) {
        return "\"" + value.replace("\"", "\"\"") + "\"";
    }
}
