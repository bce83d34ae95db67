package gfx.tick1.grade.report;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;

/**
 * Where the report's files go, and how they are written: each file is written whole to a hidden
 * temporary file in its own folder and then renamed over the target, which on POSIX file systems
 * is atomic. A grade stopped part way (Ctrl-C, a crash, a full disk) leaves the old page or the
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
        Path folder = target.toAbsolutePath().getParent();
        Files.createDirectories(folder);
        Path temporary = temporaryBeside(folder, target.getFileName().toString());
        try {
            try (OutputStream out = Files.newOutputStream(temporary)) {
                content.writeTo(out);
            }
            try {
                Files.move(temporary, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /**
     * A new hidden file in {@code folder}. Asked for as rw-rw-rw-, which the umask trims as it does
     * for any new file (usually to rw-r--r--): Files.createTempFile alone would make it, and so the
     * finished page, readable by its owner only.
     */
    private static Path temporaryBeside(Path folder, String name) throws IOException {
        String prefix = "." + name + ".";
        try {
            return Files.createTempFile(folder, prefix, ".tmp",
                    PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-rw-rw-")));
        } catch (UnsupportedOperationException e) {
            return Files.createTempFile(folder, prefix, ".tmp"); // not a POSIX file system
        }
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
