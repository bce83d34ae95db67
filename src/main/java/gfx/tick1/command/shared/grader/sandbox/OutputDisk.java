package gfx.tick1.command.shared.grader.sandbox;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

/**
 * The file system a run's output folder is on, the one folder the student's code may write. When
 * the grader is root, a tmpfs of the run's own is mounted on the folder for the run and unmounted
 * when the grader has read it ({@link #close}): the kernel then holds everything the run keeps
 * there to the tmpfs's size and number of files, named or not (a file deleted while it is held
 * open, or mapped, still takes its space and its inode until the run ends), and nothing of it is
 * on the host's disk. Otherwise the folder is on the host's disk, held only by the walk of
 * {@link OutputCount}, which sees names.
 *
 * <p>The tmpfs is a little larger than the caps of {@link OutputCount}, so that the harness's own
 * files (images, logs) have room while the code keeps below them; a run found holding more than a
 * cap, by the walk or by the file system's own count, is stopped with the cap's words. Its pages
 * are memory, which the kernel charges to the run's control group, within the run's total. Nothing
 * on it is started as a program or mapped as code ({@code noexec}).
 *
 * <p>A cohort job's warm compiler has one of the same size on its folder ({@link #mountReadable}),
 * for the class files javac writes there.
 */
final class OutputDisk implements AutoCloseable {

    /** Room beyond the caps for the harness's own files. */
    private static final long ROOM_BYTES = 16L << 20;
    private static final int ROOM_ENTRIES = 64;
    /** The tmpfs's size and number of inodes (its root folder is one). */
    static final long BYTES = OutputCount.BYTES_CAP + ROOM_BYTES;
    static final int INODES = OutputCount.ENTRIES_CAP + ROOM_ENTRIES;

    private static final Path MOUNT = Path.of("/usr/bin/mount"), UMOUNT = Path.of("/usr/bin/umount");
    /** The name the mounts show as their source, in /proc/mounts and df. */
    private static final String SOURCE = "tick1-output";
    private static final Path MOUNTS = Path.of("/proc/self/mountinfo");

    private final Path folder;
    private final boolean mounted;
    /** The tmpfs's device number, or null: the folder is its root only while it shows this one. */
    private final Object device;

    private OutputDisk(Path folder, boolean mounted, Object device) {
        this.folder = folder;
        this.mounted = mounted;
        this.device = device;
    }

    /** {@code folder} as it is, on the host's disk: only the walk holds what is written there. */
    static OutputDisk onHostDisk(Path folder) {
        return new OutputDisk(folder, false, null);
    }

    /**
     * A tmpfs of its own mounted on {@code folder}, an empty folder, owned by {@code uid} (the user
     * the run's code runs as) and no one else's.
     *
     * @throws IOException when it cannot be mounted (the grader is not root, or may not mount)
     */
    static OutputDisk mount(Path folder, int uid) throws IOException {
        return mount(folder, "mode=0700,uid=" + uid + ",gid=" + uid);
    }

    /**
     * A tmpfs of its own mounted on {@code folder}, an empty folder, owned by the grader (root) and
     * readable by {@code group} (the warm compiler's user), which may write only in the folders the
     * grader makes it there: the folder the warm compiler's class files land in.
     *
     * @throws IOException when it cannot be mounted
     */
    static OutputDisk mountReadable(Path folder, int group) throws IOException {
        return mount(folder, "mode=0750,uid=0,gid=" + group);
    }

    private static OutputDisk mount(Path folder, String owner) throws IOException {
        // noexec: nothing written there is started as a program or mapped as code, so a library with
        // code in it that the code wrote does not load. (One with no code in it still loads, and its
        // relocations write where they ask: docs/grading.md's trust model says so.)
        String options = "size=" + BYTES + ",nr_inodes=" + INODES + "," + owner + ",nosuid,nodev,noexec";
        if (!Commands.run(List.of(MOUNT.toString(), "-t", "tmpfs", "-o", options, SOURCE, folder.toString()))) {
            throw new IOException("cannot mount a file system of its own on " + folder);
        }
        try {
            return new OutputDisk(folder, true, Files.getAttribute(folder, "unix:dev"));
        } catch (IOException | RuntimeException e) {
            new OutputDisk(folder, true, null).close();
            throw e;
        }
    }

    /** Whether each run's folder can be a tmpfs of its own here: one is mounted and unmounted in {@code scratch}. */
    static boolean canMount(Path scratch) {
        try (OutputDisk disk = mount(scratch, 0)) {
            return disk.mounted;
        } catch (IOException e) {
            return false;
        }
    }

    Path folder() {
        return folder;
    }

    /**
     * Why the run holds more than the caps allow, or what cannot be counted, in words for the
     * student; or null. On a tmpfs of its own, first the file system's own count, which sees what
     * the code holds without a name: its blocks in use, and whether a file can still be made.
     */
    String overCap() {
        return overCap(folder);
    }

    /**
     * As {@link #overCap()}, but the walk counts only {@code within}, a folder on this file system
     * (the file system's own count is of all of it).
     */
    String overCap(Path within) {
        if (mounted && stillMounted()) {
            File root = folder.toFile();
            if (root.getTotalSpace() - root.getFreeSpace() > OutputCount.BYTES_CAP) {
                return OutputCount.TOO_MANY_BYTES;
            }
            if (!canMakeAFile()) {
                return OutputCount.TOO_MANY_ENTRIES;
            }
        }
        return OutputCount.overCap(within);
    }

    /**
     * Whether nothing is left on this file system: no name in its folder and, on a tmpfs of its
     * own, no block in use (a file a killed process still held takes its blocks until it is gone)
     * and still mounted there. On the host's disk, whenever the folder is there and empty: a new
     * one would be no emptier.
     */
    boolean holdsNothing() {
        try (var names = Files.list(folder)) {
            if (names.findAny().isPresent()) {
                return false;
            }
        } catch (IOException | UncheckedIOException e) {
            return false;   // not there, or not readable: nothing to start a compile on
        }
        if (!mounted) {
            return true;
        }
        File root = folder.toFile();
        return stillMounted() && root.getTotalSpace() == root.getFreeSpace();
    }

    /** Whether the folder is still the tmpfs's root: the clean-up on Ctrl-C may have detached it. */
    private boolean stillMounted() {
        try {
            return device.equals(Files.getAttribute(folder, "unix:dev"));
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /**
     * Whether a new file can be made in the folder: Java has no count of free inodes, and as root
     * nothing but their lack stops one being made there.
     */
    private boolean canMakeAFile() {
        Path probe = folder.resolve(".tick1-" + Long.toHexString(ThreadLocalRandom.current().nextLong()));
        try {
            Files.createFile(probe);
        } catch (FileAlreadyExistsException e) {
            return true;   // a name the code made: no answer, and none needed this time
        } catch (IOException e) {
            return false;
        }
        try {
            Files.deleteIfExists(probe);
        } catch (IOException e) {
            // The code put something else in its place meanwhile: it is the code's, counted by the walk.
        }
        return true;
    }

    /**
     * Detaches every run's tmpfs mounted at or below {@code folder} (on Ctrl-C or SIGTERM the
     * clean-up may come while a run's is still mounted), so that deleting the folder reaches
     * everything in it. Does nothing where none is. Never throws.
     */
    static void detachAllUnder(Path folder) {
        String top;
        Path absolute = folder.toAbsolutePath();
        try {
            // The folder itself is not resolved: a link put in its place must not lead to another run's mounts.
            if (absolute.getParent() == null || !Files.isDirectory(absolute, LinkOption.NOFOLLOW_LINKS)) {
                return;   // no folder, no mount on it
            }
            top = absolute.getParent().toRealPath().resolve(absolute.getFileName()).toString();
        } catch (IOException e) {
            return;
        }
        List<String> below = new ArrayList<>();
        for (String point : mountPoints()) {
            if (point.equals(top) || point.startsWith(top + "/")) {
                below.add(point);
            }
        }
        below.sort(Comparator.comparing(String::length).reversed());   // the deepest first
        below.forEach(OutputDisk::detach);
    }

    /** Where a run's or a compiler's tmpfs (source {@code tick1-output}) is mounted; none where that cannot be read. */
    static List<String> mountPoints() {
        List<String> lines;
        try {
            lines = Files.readAllLines(MOUNTS);
        } catch (IOException | RuntimeException e) {
            return List.of();
        }
        List<String> points = new ArrayList<>();
        for (String line : lines) {
            // mountinfo: ID PARENT MAJOR:MINOR ROOT MOUNT-POINT OPTIONS ... - TYPE SOURCE SUPER-OPTIONS
            String[] halves = line.split(" - ", 2);
            String[] fields = halves[0].split(" ");
            if (halves.length == 2 && fields.length > 4 && halves[1].startsWith("tmpfs " + SOURCE + " ")) {
                points.add(unescape(fields[4]));
            }
        }
        return points;
    }

    /** Detaches the file system mounted at {@code point} (it goes when nothing holds it); whether umount did. */
    static boolean detach(String point) {
        return Commands.run(List.of(UMOUNT.toString(), "--lazy", point));
    }

    /** A mount point as mountinfo writes it, with its space, tab, newline and backslash as octal escapes. */
    private static String unescape(String field) {
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < field.length(); i++) {
            char c = field.charAt(i);
            if (c == '\\' && i + 3 < field.length() && field.substring(i + 1, i + 4).chars().allMatch(
                    digit -> digit >= '0' && digit <= '7')) {
                text.append((char) Integer.parseInt(field.substring(i + 1, i + 4), 8));
                i += 3;
            } else {
                text.append(c);
            }
        }
        return text.toString();
    }

    /**
     * Unmounts the tmpfs, and with it everything the run left there; the folder is then empty.
     * Detaches it where something still holds it (it goes when that ends). Never throws.
     */
    @Override
    public void close() {
        if (mounted && !Commands.run(List.of(UMOUNT.toString(), folder.toString()))) {
            Commands.run(List.of(UMOUNT.toString(), "--lazy", folder.toString()));
        }
    }
}
