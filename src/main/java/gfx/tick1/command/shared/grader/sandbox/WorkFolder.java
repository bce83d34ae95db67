package gfx.tick1.command.shared.grader.sandbox;

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
import java.util.List;
import java.util.regex.Pattern;

/**
 * The folders {@code grade} cleans: its work folder, which holds the hidden scenes and whatever
 * the student's process wrote, and the report folder's images of an earlier grade.
 */
public final class WorkFolder {

    /** The names {@code grade} gives report images: 2-hidden-diff.png, 1-tick1-yours.png, ... */
    private static final Pattern REPORT_IMAGE = Pattern.compile("\\d+-.+-(diff|yours|expected)\\.png");

    /**
     * The free space a grade's work folder may need for one run: what the run's output folder may
     * hold ({@link OutputCount#BYTES_CAP}). With less, a run that writes that much may fill the disk.
     */
    public static final long RUN_SPACE = OutputCount.BYTES_CAP;

    /**
     * The free files and folders (inodes) a grade's work folder needs for one run: what the run's
     * output folder may hold ({@link OutputCount#ENTRIES_CAP}). With fewer, a run that makes that
     * many may fill the disk.
     */
    public static final long RUN_FILES = OutputCount.ENTRIES_CAP;

    private WorkFolder() {
    }

    /**
     * Deletes {@code folder} and everything in it, following no link, and whatever the student's
     * process did to the permissions of what it wrote. Never throws: it runs on the way out,
     * Ctrl-C and SIGTERM included; it may run twice at once (the shutdown hook and the command).
     *
     * @return null, or why the folder could not be deleted, in one line that names only the work
     *     folder itself (the names inside it are the student's, and may hold anything)
     */
    public static synchronized String delete(Path folder) {
        OutputDisk.detachAllUnder(folder);   // a run's file system still mounted there, on Ctrl-C
        if (deleteByWalking(folder) || deleteWithRm(folder)) {
            return null;
        }
        return "cannot delete the work folder " + folder + ": delete it by hand (it may hold hidden scenes)";
    }

    /** Whether walking the tree deleted it all. */
    private static boolean deleteByWalking(Path folder) {
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
            return true;   // already deleted
        } catch (IOException e) {
            return false;
        }
        return !Files.exists(folder, LinkOption.NOFOLLOW_LINKS);
    }

    /**
     * Whether {@code chmod -R u+rwx} then {@code rm -rf} deleted the tree. The student's code can
     * make a tree deeper than a path may be long (PATH_MAX, 4096 bytes), which no deletion by
     * whole paths can reach; GNU chmod and rm descend folder by folder, relative to each one they
     * have open, at any depth, and neither follows a link. chmod first, because below that depth
     * the walk above could not undo what the code did to permissions (it runs as the grader's
     * user when the grader is not root).
     */
    private static boolean deleteWithRm(Path folder) {
        String name = folder.toString();
        Commands.run(List.of("/bin/chmod", "-R", "u+rwx", "--", name));   // what it cannot change, rm reports
        return Commands.run(List.of("/bin/rm", "-rf", "--one-file-system", "--", name))
                && !Files.exists(folder, LinkOption.NOFOLLOW_LINKS);
    }

    /**
     * Deletes the images an earlier grade wrote into {@code report}, so that the folder shows this
     * grade's images only. Only regular files with the names grade gives are touched.
     */
    public static void removeEarlierReport(Path report) throws IOException {
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
