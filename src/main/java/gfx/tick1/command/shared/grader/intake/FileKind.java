package gfx.tick1.command.shared.grader.intake;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.ByteBuffer;
import java.util.List;
import java.util.Optional;

/**
 * What a file given as a download is, when its first bytes show plainly that it is not a zip, so
 * that the message says what was given ("a text file", "a CSV file") and what was wanted. Anything else goes to
 * the zip reader, which says what is wrong with it. A path that is neither a file nor a folder is named
 * for what it is, too.
 */
final class FileKind {

    /** How many bytes are looked at. */
    private static final int HEAD = 512;

    private FileKind() {
    }

    /**
     * What {@code path}, neither a file nor a folder, is: "no such file or folder", or "a named pipe, not ...",
     * "a device, not ..." or "a socket, not ..." (its type, from its mode: Java has no words for them).
     */
    static String notAFileOrFolder(Path path) {
        int mode;
        try {
            mode = (Integer) Files.getAttribute(path, "unix:mode");
        } catch (IOException | RuntimeException e) {
            return Files.exists(path, LinkOption.NOFOLLOW_LINKS) ? "neither a file nor a folder"
                    : "no such file or folder";
        }
        // The file type is the mode's bits S_IFMT (0170000), in octal as stat(2) gives them: S_IFIFO 0010000,
        // S_IFCHR 0020000, S_IFBLK 0060000, S_IFSOCK 0140000.
        String kind = switch (mode & 0170000) {
            case 0010000 -> "a named pipe";
            case 0020000, 0060000 -> "a device";
            case 0140000 -> "a socket";
            default -> "neither a file nor a folder";
        };
        return kind + ", not Moodle's \"Download all submissions\" zip or the folder it unpacks to";
    }

    /**
     * "an empty file", "a CSV file" (lines of commas), "a text file" (any other text), "a PNG image", "a gzip
     * file", "a RAR archive", "a 7-Zip archive"; empty when the file may be a zip (or cannot be read: the zip
     * reader says why).
     */
    static Optional<String> unlessZip(Path file) {
        byte[] head;
        try (InputStream in = Files.newInputStream(file)) {
            head = in.readNBytes(HEAD);
        } catch (IOException e) {
            return Optional.empty();
        }
        if (head.length == 0) {
            return Optional.of("an empty file");
        }
        if (startsWith(head, 'P', 'K')) {
            return Optional.empty();
        }
        if (startsWith(head, 0x89, 'P', 'N', 'G')) {
            return Optional.of("a PNG image");
        }
        if (startsWith(head, 0x1F, 0x8B)) {
            return Optional.of("a gzip file");
        }
        if (startsWith(head, 'R', 'a', 'r', '!')) {
            return Optional.of("a RAR archive");
        }
        if (startsWith(head, '7', 'z', 0xBC, 0xAF)) {
            return Optional.of("a 7-Zip archive");
        }
        if (isText(head)) {
            return Optional.of(isCsv(new String(head, StandardCharsets.UTF_8)) ? "a CSV file" : "a text file");
        }
        return Optional.empty();
    }

    /**
     * Whether text reads as CSV: its first two lines hold the same number of commas, at least one. A
     * comma in a line of prose does not make a file CSV; a header and a row of the same width do.
     */
    private static boolean isCsv(String text) {
        List<Long> commas = text.lines().limit(2).map(line -> line.chars().filter(c -> c == ',').count()).toList();
        return commas.size() == 2 && commas.get(0) > 0 && commas.get(0).equals(commas.get(1));
    }

    private static boolean startsWith(byte[] bytes, int... prefix) {
        if (bytes.length < prefix.length) {
            return false;
        }
        for (int i = 0; i < prefix.length; i++) {
            if ((bytes[i] & 0xFF) != prefix[i]) {
                return false;
            }
        }
        return true;
    }

    /** UTF-8 (a character cut at the end of the head allowed) without control characters but tab, CR and LF. */
    private static boolean isText(byte[] head) {
        for (byte b : head) {
            if ((b & 0xFF) < 0x20 && b != '\t' && b != '\r' && b != '\n' || b == 0x7F) {
                return false;
            }
        }
        int end = head.length;
        // Drop a character cut short by the end of the head: up to three continuation bytes and their lead.
        for (int back = 0; back < 3 && end > 0 && (head[end - 1] & 0xC0) == 0x80; back++) {
            end--;
        }
        if (end > 0 && (head[end - 1] & 0xC0) == 0xC0) {
            end--;
        }
        try {
            StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(head, 0, end));
            return true;
        } catch (CharacterCodingException e) {
            return false;
        }
    }
}
