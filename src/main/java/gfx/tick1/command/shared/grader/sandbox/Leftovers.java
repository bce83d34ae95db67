package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * What tick1 runs killed before their clean-up (SIGKILL, a power cut) left on the machine: the
 * tmpfs mounted on their runs' and compilers' folders (source {@code tick1-output}), their work
 * folders ({@code tick1-grade-PID-...}, and those of the behaviour check and of {@code tick1 vpl}'s check of the
 * scenes, all made by {@link #newWorkFolder}, and the private folder of the VPL script {@code tick1 vpl} writes,
 * {@code tick1-vpl-PID-...}, whose PID is the script's bash), seccomp filter files ({@code tick1-seccomp-PID-....bpf})
 * and control groups ({@code tick1-PID-N}). Each name carries the process id of the run that made
 * it; what belongs to a process that is gone, and is owned by this process's user, is removed
 * (anyone may make a folder with such a name, to steer a removal run as root). A live process
 * under that id is left alone when it is a Java program (tick1 always is one) or bash (the VPL
 * script), or when what it runs cannot be told.
 */
public final class Leftovers {

    private static final Pattern WORK_FOLDER = Pattern.compile("tick1-(?:grade|mount|behaviour|vpl)-(\\d+)-.+");
    private static final Pattern FILTER_FILE = Pattern.compile("tick1-seccomp-(\\d+)-.+\\.bpf");
    private static final Pattern CONTROL_GROUP = Pattern.compile("tick1-(\\d+)-\\d+");
    private static final Pattern MARKED = Pattern.compile("(\\d+)-.*");
    /** The most names the line of what could not be removed shows. */
    private static final int SHOWN = 3;

    private Leftovers() {
    }

    /**
     * The prefix of a new file or folder of this run's in the temporary folder, for {@code use}
     * ("grade", "seccomp", ...): it carries this process's id, so that what a killed run left can be
     * told from what a live one holds.
     */
    static String prefix(String use) {
        return "tick1-" + use + "-" + mark();
    }

    /** This process's id and a dash: the start of a name that {@link #leftByAGoneRun} can read back. */
    public static String mark() {
        return ProcessHandle.current().pid() + "-";
    }

    /**
     * Whether {@code name}, which starts with a {@link #mark}, was left by a run whose process is {@link #gone}.
     * A name that starts with no process id was made by an older tick1, which did not mark its names, and is
     * taken as left.
     */
    public static boolean leftByAGoneRun(String name) {
        Long owner = owner(MARKED, name);
        return owner == null || gone(owner);
    }

    /** A new work folder for {@code use} ("grade", "mount") in the temporary folder, named by {@link #prefix}. */
    public static Path newWorkFolder(String use) throws IOException {
        return Files.createTempDirectory(prefix(use));
    }

    /**
     * Removes what tick1 runs whose process is gone left in the temporary folder, in the mounts and
     * where this process makes its control groups.
     *
     * @return null, or one line naming what could not be removed
     */
    public static String remove() {
        return remove(Path.of(System.getProperty("java.io.tmpdir")), Cgroup.find());
    }

    /** As {@link #remove()}, with {@code temporary} for the temporary folder and {@code cgroups} (or null). */
    static String remove(Path temporary, Cgroup.Place cgroups) {
        List<String> left = new ArrayList<>();
        // The mounts first: a folder with a file system mounted in it cannot be deleted.
        List<String> points = new ArrayList<>(OutputDisk.mountPoints());
        points.sort(Comparator.comparing(String::length).reversed());   // the deepest first
        for (String point : points) {
            Path folder = workFolderOf(Path.of(point));
            Long owner = folder == null ? null : owner(WORK_FOLDER, folder.getFileName().toString());
            if (owner != null && gone(owner) && ThisUser.owns(folder) && !OutputDisk.detach(point)) {
                left.add(point);
            }
        }
        for (Path entry : list(temporary)) {
            String name = entry.getFileName().toString();
            Long folderOwner = owner(WORK_FOLDER, name);
            if (folderOwner != null && gone(folderOwner) && Files.isDirectory(entry, LinkOption.NOFOLLOW_LINKS)
                    && ThisUser.owns(entry) && WorkFolder.delete(entry) != null) {
                left.add(entry.toString());
            }
            Long fileOwner = owner(FILTER_FILE, name);
            if (fileOwner != null && gone(fileOwner) && ThisUser.owns(entry) && !deleted(entry)) {
                left.add(entry.toString());
            }
        }
        for (Path parent : cgroups == null ? List.<Path>of() : cgroups.parents().values()) {
            for (Path group : list(parent)) {
                Long owner = owner(CONTROL_GROUP, group.getFileName().toString());
                if (owner != null && gone(owner) && Files.isDirectory(group, LinkOption.NOFOLLOW_LINKS)
                        && ThisUser.owns(group) && !deleted(group)) {
                    left.add(group.toString());
                }
            }
        }
        return left.isEmpty() ? null : "cannot remove what killed tick1 runs left: " + String.join(", ",
                left.subList(0, Math.min(SHOWN, left.size()))) + (left.size() > SHOWN ? " and "
                + (left.size() - SHOWN) + " more" : "") + " (remove them by hand: umount, rmdir, rm -r)";
    }

    /** The work folder on the way to {@code path}, an absolute mount point, or null. */
    private static Path workFolderOf(Path path) {
        for (int i = 1; i <= path.getNameCount(); i++) {
            if (owner(WORK_FOLDER, path.getName(i - 1).toString()) != null) {
                return path.getRoot().resolve(path.subpath(0, i));
            }
        }
        return null;
    }

    private static Long owner(Pattern pattern, String name) {
        Matcher matcher = pattern.matcher(name);
        try {
            return matcher.matches() ? Long.valueOf(matcher.group(1)) : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /**
     * Whether the process {@code pid} is gone: not there, or running a program that is neither Java
     * nor bash (its id taken again). A live Java program, or one whose program cannot be told, may be
     * tick1; a live bash may be the VPL script.
     */
    static boolean gone(long pid) {
        Optional<ProcessHandle> process = ProcessHandle.of(pid).filter(ProcessHandle::isAlive);
        return process.isEmpty() || process.get().info().command().map(command -> Path.of(command).getFileName()
                .toString()).map(program -> !program.startsWith("java") && !program.equals("bash")).orElse(false);
    }

    private static List<Path> list(Path folder) {
        try (Stream<Path> entries = Files.list(folder)) {
            return entries.toList();
        } catch (IOException | UncheckedIOException e) {
            return List.of();   // not there, or not ours to read: nothing of ours left in it
        }
    }

    /** Whether {@code path}, a file or an empty folder (a control group), was deleted or was already gone. */
    private static boolean deleted(Path path) {
        try {
            Files.deleteIfExists(path);
            return true;
        } catch (IOException e) {
            return false;
        }
    }
}
