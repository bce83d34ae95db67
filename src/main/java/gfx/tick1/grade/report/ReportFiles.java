package gfx.tick1.grade.report;

import gfx.tick1.io.AtomicFile;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Where the report's files go, and how they are written: each file is written whole to a hidden
 * temporary file in its own folder and then renamed over the target ({@link AtomicFile}), which on
 * POSIX file systems is atomic. A grade stopped part way (Ctrl-C, a crash, a full disk) leaves the old page or the
 * new one, never half of one; at worst a {@code .NAME.RANDOM.tmp} beside it.
 */
public final class ReportFiles {

    /** The report folder's sub-folder holding one folder of feedback per student. */
    static final String FEEDBACK = "feedback";

    /** The gradebook in the report folder, in the form of Moodle's grading worksheet. */
    public static final String GRADES = "grades.csv";

    /** Every student's feedback files, in the zip Moodle's "Upload multiple feedback files in a zip" reads. */
    public static final String FEEDBACK_ZIP = "feedback.zip";

    /** Writes a file's bytes onto a stream; the stream is closed by the caller. */
    @FunctionalInterface
    public interface Content {
        void writeTo(OutputStream out) throws IOException;
    }

    private ReportFiles() {
    }

    static void write(Path target, String text) throws IOException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        write(target, out -> out.write(bytes));
    }

    public static void write(Path target, Content content) throws IOException {
        Files.createDirectories(target.toAbsolutePath().getParent());
        AtomicFile.write(target, content::writeTo);
    }

    /**
     * {@code name} as one plain entry of a folder, the one way the report makes a name safe: a
     * separator, NUL, a C0 or C1 control character or a bidirectional formatting mark becomes
     * {@code _} (a control would be obeyed by a terminal listing the folder, a bidi mark can make
     * one name read as another), and an empty name, {@code .} or {@code ..} gains a leading
     * {@code _}. Moodle's own folder names pass unchanged.
     */
    public static String plainName(String name) {
        StringBuilder out = new StringBuilder(name.length());
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            out.append(c == '/' || c == '\\' || c < 0x20 || c >= 0x7F && c <= 0x9F || isBidiMark(c) ? '_' : c);
        }
        String plain = out.toString();
        return plain.isEmpty() || plain.equals(".") || plain.equals("..") ? "_" + plain : plain;
    }

    /** The marks that change the direction of text: LRM, RLM, ALM and the embeddings, overrides and isolates. */
    private static boolean isBidiMark(char c) {
        return c == '\u200E' || c == '\u200F' || c == '\u061C' || c >= '\u202A' && c <= '\u202E'
                || c >= '\u2066' && c <= '\u2069';
    }

    /**
     * Whether {@code name} is one plain entry of a folder, as {@link #plainName} makes it. Only such
     * names are joined to the report folder, so nothing a submission is called can place a file,
     * or a link, outside it.
     */
    static boolean isPlainName(String name) {
        return name != null && plainName(name).equals(name);
    }

    /** {@code report/feedback/<folder>}; the folder's name must be plain (see {@link #isPlainName}). */
    public static Path feedbackFolder(Path report, String folder) {
        if (!isPlainName(folder)) {
            throw new IllegalArgumentException("a submission folder named \"" + folder
                    + "\" cannot be a folder of the report: it must be one plain name");
        }
        return report.resolve(FEEDBACK).resolve(folder);
    }
}
