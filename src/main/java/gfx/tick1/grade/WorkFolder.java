package gfx.tick1.grade;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.regex.Pattern;

/**
 * The folders {@code grade} cleans: its work folder, which holds the hidden scenes and whatever
 * the student's process wrote, and the report folder's images of an earlier grade.
 */
final class WorkFolder {

    /** The names {@code grade} gives report images: 2-hidden-diff.png, 1-tick1-yours.png, ... */
    private static final Pattern REPORT_IMAGE = Pattern.compile("\\d+-.+-(diff|yours|expected)\\.png");

    private WorkFolder() {
    }

    /**
     * Deletes {@code folder} and everything in it, following no link, and whatever the student's
     * process did to the permissions of what it wrote. Never throws: it runs on the way out,
     * Ctrl-C and SIGTERM included; it may run twice at once (the shutdown hook and the command).
     *
     * @return null, or why the folder could not be deleted, in one line
     */
    static synchronized String delete(Path folder) {
        try {
            Files.walkFileTree(folder, new SimpleFileVisitor<>() {
                @Override
                public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attributes) {
                    // A folder the student made unreadable must still be listed to be emptied.
                    try {
                        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx------"));
                    } catch (IOException | UnsupportedOperationException e) {
                        // Not ours to change (root needs no permission): go on.
                    }
                    return FileVisitResult.CONTINUE;
                }

                @Override
                public FileVisitResult visitFile(Path file, BasicFileAttributes attributes) throws IOException {
                    Files.deleteIfExists(file);
                    return FileVisitResult.CONTINUE;
                }

                @Override
                public FileVisitResult visitFileFailed(Path file, IOException e) throws IOException {
                    Files.deleteIfExists(file);
                    return FileVisitResult.CONTINUE;
                }

                @Override
                public FileVisitResult postVisitDirectory(Path dir, IOException e) throws IOException {
                    Files.deleteIfExists(dir);
                    return FileVisitResult.CONTINUE;
                }
            });
        } catch (NoSuchFileException e) {
            // Already deleted.
        } catch (IOException e) {
            return "cannot delete the work folder " + folder + ": " + e.getMessage();
        }
        return null;
    }

    /**
     * Deletes the images an earlier grade wrote into {@code report}, so that the folder shows this
     * grade's images only. Only regular files with the names grade gives are touched.
     */
    static void removeEarlierReport(Path report) throws IOException {
        if (!Files.isDirectory(report, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (DirectoryStream<Path> files = Files.newDirectoryStream(report)) {
            for (Path file : files) {
                if (REPORT_IMAGE.matcher(file.getFileName().toString()).matches()
                        && Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS)) {
                    Files.delete(file);
                }
            }
        }
    }
}
