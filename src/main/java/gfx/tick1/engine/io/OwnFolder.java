package gfx.tick1.engine.io;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * A folder tick1 keeps inside a folder the user gave it (the report's feedback folders, the cohort's state), made
 * when absent and never a link: a symbolic link found where the folder belongs is removed, never followed, and a
 * folder made in its place; anything else there that is not a folder is refused and left as it is. So what tick1
 * writes or deletes in it stays inside the user's folder, even when tick1 runs as root.
 *
 * <p>The check and the making are two steps: a process that may write in the user's folder could put a link there
 * between them. The user's folder should therefore be writable by its user alone.
 */
public final class OwnFolder {

    private OwnFolder() {
    }

    /** {@code folder}, a folder and not a link, made if need be; its parent must exist. */
    public static Path at(Path folder) throws IOException {
        BasicFileAttributes attributes;
        try {
            attributes = Files.readAttributes(folder, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
        } catch (NoSuchFileException e) {
            return made(folder);
        }
        if (attributes.isSymbolicLink()) {
            Files.delete(folder);   // the link itself, not what it names
            return made(folder);
        }
        if (!attributes.isDirectory()) {
            throw new FileSystemException(folder.toString(), null, "not a folder, where tick1 keeps a folder of its "
                    + "own; move it away");
        }
        return folder;
    }

    private static Path made(Path folder) throws IOException {
        try {
            return Files.createDirectory(folder);
        } catch (FileAlreadyExistsException e) {
            throw new FileSystemException(folder.toString(), null, "made by another process while tick1 made it");
        }
    }
}
