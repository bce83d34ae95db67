package gfx.tick1.engine.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;

/**
 * Writes a file whole or not at all: to a hidden temporary file beside the target, renamed over the target only once
 * complete. A rename within one folder is atomic on POSIX file systems, so readers see the old file or the new one.
 * If the write fails (a full disk, say) the temporary file is deleted and the exception passed on; if the JVM is
 * stopped meanwhile a shutdown hook deletes it, and a write begun once the JVM is stopping is refused
 * ({@link OnExit#run}). Only a hard kill can leave one behind: a hidden {@code .NAME.RANDOM.tmp}, never the target
 * itself. A link at the target is replaced by the file (the rename
 * replaces it), never written through.
 */
public final class AtomicFile {

    /** Writes a file's bytes onto a stream; the stream is closed by the caller. */
    @FunctionalInterface
    public interface Content {
        void writeTo(OutputStream out) throws IOException;
    }

    private AtomicFile() {
    }

    /**
     * Writes {@code content} to {@code target}, whose folder exists.
     *
     * @param cannotCreate what to throw when the temporary file cannot be created in the folder
     */
    public static void write(Path target, Content content, CannotCreate cannotCreate) throws IOException {
        Path absolute = target.toAbsolutePath();
        Path temporary;
        try {
            temporary = temporaryBeside(absolute);
        } catch (IOException e) {
            throw cannotCreate.map(e);
        }
        OnExit deleted = OnExit.run("tick1-delete-temporary-file", () -> deleteQuietly(temporary));
        try {
            // The temporary file is new and tick1's: a link put in its place meanwhile is not written through.
            try (OutputStream out = Files.newOutputStream(temporary, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING, LinkOption.NOFOLLOW_LINKS)) {
                content.writeTo(out);
            }
            try {
                Files.move(temporary, absolute, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temporary, absolute, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            deleted.now();
        }
    }

    /** Writes {@code content} to {@code target}, whose folder exists, passing any failure on as it is. */
    public static void write(Path target, Content content) throws IOException {
        write(target, content, e -> e);
    }

    /** The exception to throw for one that creating the temporary file threw. */
    @FunctionalInterface
    public interface CannotCreate {
        IOException map(IOException e);
    }

    /**
     * A new hidden file beside {@code target}. Asked for as rw-rw-rw-, which the umask trims as it does for any new
     * file (usually to rw-r--r--): Files.createTempFile alone would make it, and so the finished file, readable by
     * its owner only.
     */
    private static Path temporaryBeside(Path target) throws IOException {
        Path folder = target.getParent();
        String prefix = "." + target.getFileName() + ".";
        try {
            return Files.createTempFile(folder, prefix, ".tmp",
                    PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-rw-rw-")));
        } catch (UnsupportedOperationException e) {
            return Files.createTempFile(folder, prefix, ".tmp"); // not a POSIX file system
        }
    }

    private static void deleteQuietly(Path file) {
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            // Nothing more can be done; the name starts with a dot and ends in .tmp.
        }
    }
}
