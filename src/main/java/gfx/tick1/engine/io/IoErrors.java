package gfx.tick1.engine.io;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;

/**
 * The one wording of a failed file operation for a person: the same error reads the same
 * whichever command meets it. Java's own messages are a file name, or a name and the operating
 * system's reason; these say what went wrong in a few plain words.
 */
public final class IoErrors {

    private IoErrors() {
    }

    /** What went wrong, without the file's name: for a message that names the file itself. */
    public static String reason(IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileAlreadyExistsException) {
            // Files.createDirectories, the only way tick1 meets it, finding a file where a folder goes.
            return "exists and is not a folder";
        }
        if (e instanceof NotDirectoryException) {
            return "not a folder";
        }
        if (e instanceof CharacterCodingException) {
            return "not UTF-8 text";
        }
        if (e instanceof FileSystemException fileSystem && fileSystem.getReason() != null) {
            return fileSystem.getReason();
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }

    /** The file the error is about, if Java names it, then what went wrong: a whole message. */
    public static String describe(IOException e) {
        if (e instanceof FileSystemException fileSystem && fileSystem.getFile() != null) {
            return fileSystem.getFile() + ": " + reason(e);
        }
        return reason(e);
    }
}
