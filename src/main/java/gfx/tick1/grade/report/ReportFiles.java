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
     * Whether {@code name} is one plain entry of a folder: not empty, not {@code .} or {@code ..},
     * and without a separator or NUL. Only such names are joined to the report folder, so nothing
     * a submission is called can place a file, or a link, outside it.
     */
    static boolean isPlainName(String name) {
        return name != null && !name.isEmpty() && !name.equals(".") && !name.equals("..")
                && name.indexOf('/') < 0 && name.indexOf('\\') < 0 && name.indexOf('\0') < 0;
    }

    /** {@code report/feedback/<folder>}; the folder's name must be plain (see {@link #isPlainName}). */
    static Path feedbackFolder(Path report, String folder) {
        if (!isPlainName(folder)) {
            throw new IllegalArgumentException("a submission folder named \"" + folder
                    + "\" cannot be a folder of the report: it must be one plain name");
        }
        return report.resolve(FEEDBACK).resolve(folder);
    }
}
