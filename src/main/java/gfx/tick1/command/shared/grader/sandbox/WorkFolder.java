package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.SecureDirectoryStream;
import java.nio.file.attribute.BasicFileAttributeView;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
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
     * Lets every user read {@code folder} and the files in it, and none write those files: for the harness's jar
     * and its archive, which the runs of other users (a cohort's jobs) read. Only for a folder that tick1 alone wrote,
     * of files and nothing secret: it follows links, and a folder inside would become one nobody can enter.
     */
    public static void readableByAll(Path folder) throws IOException {
        Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwxr-xr-x"));
        try (var files = Files.list(folder)) {
            for (Path file : files.toList()) {
                Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("r--r--r--"));
            }
        }
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

    /**
     * Whether walking the tree deleted it all. Each folder is opened relative to the one that holds
     * it, refusing a link (openat with O_NOFOLLOW), and each name is unlinked relative to its open
     * folder, so a folder swapped for a link while the walk runs leads nowhere: nothing outside the
     * tree is deleted, and no permission is changed through a link.
     */
    private static boolean deleteByWalking(Path folder) {
        Path absolute = folder.toAbsolutePath();
        if (absolute.getParent() == null) {
            return false;
        }
        try (DirectoryStream<Path> parent = Files.newDirectoryStream(absolute.getParent())) {
            if (!(parent instanceof SecureDirectoryStream<Path> secure)) {
                return false;   // no openat here: rm, which walks by open folders too
            }
            deleteIn(secure, absolute.getFileName());
        } catch (NoSuchFileException e) {
            return true;   // already deleted
        } catch (IOException | RuntimeException e) {
            return false;
        }
        return !Files.exists(folder, LinkOption.NOFOLLOW_LINKS);
    }

    /** Deletes {@code name} in the open folder {@code parent}: a link or a file itself, a folder with all in it. */
    private static void deleteIn(SecureDirectoryStream<Path> parent, Path name) throws IOException {
        BasicFileAttributes attributes = parent.getFileAttributeView(name, BasicFileAttributeView.class,
                LinkOption.NOFOLLOW_LINKS).readAttributes();
        if (!attributes.isDirectory()) {
            parent.deleteFile(name);   // a link swapped in since is unlinked itself
            return;
        }
        List<Path> names = new ArrayList<>();
        try (SecureDirectoryStream<Path> child = open(parent, name)) {
            child.forEach(entry -> names.add(entry.getFileName()));
            for (Path entry : names) {
                deleteIn(child, entry);
            }
        }
        parent.deleteDirectory(name);   // fails on a link swapped in since (ENOTDIR), deleting nothing
    }

    /**
     * The folder {@code name} in {@code parent}, opened refusing a link. A folder the student made
     * unreadable is first given back to its owner, through a descriptor opened refusing a link too.
     */
    private static SecureDirectoryStream<Path> open(SecureDirectoryStream<Path> parent, Path name)
            throws IOException {
        try {
            return parent.newDirectoryStream(name, LinkOption.NOFOLLOW_LINKS);
        } catch (AccessDeniedException e) {
            parent.getFileAttributeView(name, PosixFileAttributeView.class, LinkOption.NOFOLLOW_LINKS)
                    .setPermissions(PosixFilePermissions.fromString("rwx------"));
            return parent.newDirectoryStream(name, LinkOption.NOFOLLOW_LINKS);
        }
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
        if (!ThisUser.root()) {
            // chmod changes what a link given to it, or swapped in under it, leads to; root needs no permission
            // to delete, and any other user can change only its own files
            Commands.run(List.of("/bin/chmod", "-R", "u+rwx", "--", name));   // what it cannot change, rm reports
        }
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
