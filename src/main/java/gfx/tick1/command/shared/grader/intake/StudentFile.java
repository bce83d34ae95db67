package gfx.tick1.command.shared.grader.intake;

import gfx.tick1.engine.io.BoundedFile;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Optional;

/**
 * A student's source file as the tester reads it: UTF-8 text (a byte-order mark, which some
 * editors write, is accepted and dropped) declaring {@code package gfx.tick1;}. Read by the grader
 * before anything of the student's is compiled or run.
 */
public final class StudentFile {

    /** The package the starter code and so every submitted file is in (handout section 2). */
    public static final String PACKAGE = "gfx.tick1";

    /** The longest package name a message quotes whole. */
    private static final int QUOTED_NAME_CAP = 100;

    private StudentFile() {
    }

    /** A student file that is not UTF-8 text: the message names the file, the line, the column and the byte. */
    public static final class NotUtf8Exception extends IOException {
        private static final long serialVersionUID = 1L;

        NotUtf8Exception(String message) {
            super(message);
        }
    }

    /** A student file larger than any real one (or a device, or a stream without end): the message names it. */
    public static final class TooLargeException extends IOException {
        private static final long serialVersionUID = 1L;

        TooLargeException(String message) {
            super(message);
        }
    }

    /** The text of {@code file}, read as {@link #readBytes(Path)} reads it, as UTF-8, without a byte-order mark. */
    public static String read(Path file) throws IOException {
        return decode(file.toString(), readBytes(file));
    }

    /**
     * The bytes of a student's file named on the command line, read no further than the intake reads a student's
     * file in a download: a device or an endless stream given in its place ends in one line.
     *
     * @throws TooLargeException past that bound
     */
    public static byte[] readBytes(Path file) throws IOException {
        long bound = IntakeLimits.DEFAULT.maxFileBytes();
        try {
            return BoundedFile.read(file, bound);
        } catch (BoundedFile.TooLarge e) {
            throw new TooLargeException(file + ": " + e.getMessage() + ", far more than any Sphere.java or "
                    + "Renderer.java");
        }
    }

    /** {@code bytes} as UTF-8 text without a leading byte-order mark; errors name {@code name}. */
    public static String decode(String name, byte[] bytes) throws NotUtf8Exception {
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length + 1);
        CoderResult result = decoder.decode(in, out, true);
        if (result.isError()) {
            throw notUtf8(name, bytes, in.position());
        }
        decoder.flush(out);
        String text = out.flip().toString();
        return text.startsWith("\uFEFF") ? text.substring(1) : text;
    }

    private static NotUtf8Exception notUtf8(String name, byte[] bytes, int offset) {
        int line = 1, lineStart = 0;
        for (int i = 0; i < offset; i++) {
            if (bytes[i] == '\n') {
                line++;
                lineStart = i + 1;
            }
        }
        int column;
        try {
            column = StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(bytes, lineStart, offset - lineStart))
                    .length() + 1;
        } catch (CharacterCodingException e) {
            column = offset - lineStart + 1;
        }
        return new NotUtf8Exception(String.format("%s:%d:%d: not UTF-8 text: byte 0x%02X is not part of a UTF-8 "
                + "character; save the file as UTF-8", name, line, column, bytes[offset] & 0xFF));
    }

    /**
     * Why the tester cannot use {@code code} from the file {@code name} as a file of package
     * gfx.tick1, in one line; empty when it declares that package.
     */
    public static Optional<String> packageProblem(String name, String code) {
        JavaDeclarations.PackageClause clause = JavaDeclarations.packageOf(code);
        String said;
        if (clause instanceof JavaDeclarations.PackageClause.Declared declared) {
            if (declared.name().equals(PACKAGE)) {
                return Optional.empty();
            }
            said = "declares package " + quoted(declared.name());
        } else if (clause instanceof JavaDeclarations.PackageClause.BeyondCap) {
            said = "declares no package within its first " + JavaDeclarations.PACKAGE_SCAN_CAP
                    + " characters (comments and blank lines included)";
        } else {
            said = "declares no package";
        }
        return Optional.of(name + ": the tester needs the file in package " + PACKAGE + " (its first line \"package "
                + PACKAGE + ";\", as in the starter code), but it " + said);
    }

    private static String quoted(String declared) {
        return declared.length() <= QUOTED_NAME_CAP ? declared
                : declared.substring(0, QUOTED_NAME_CAP) + "... (" + declared.length() + " characters)";
    }
}
