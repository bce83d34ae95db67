package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A control group of its own for one run in the sandbox, so that the kernel holds all of the run's
 * processes together to totals: memory (what they allocate, and what they keep in tmpfs and
 * shared memory, which the kernel charges to the group), processes and threads, and one core's
 * worth of processor time. cgroup v2 where the unified hierarchy lets this process make a group
 * with the memory and pids controllers; cgroup v1 where the memory and pids hierarchies are
 * mounted and the groups this process is in are writable. The run's first process joins the
 * group before it starts anything ({@link #folders}); the group is removed afterwards.
 */
final class Cgroup implements AutoCloseable {

    private static final Path PROC_CGROUP = Path.of("/proc/self/cgroup");
    private static final Path MOUNTS = Path.of("/proc/self/mountinfo");
    private static final long CPU_PERIOD_MICROS = 100_000;
    private static final AtomicLong NEXT = new AtomicLong();
    /** How many names a new group may try, when earlier processes left groups under this process id. */
    private static final int NAME_TRIES = 1000;
    /** How many times the removal of a group is tried, a millisecond apart. */
    private static final int REMOVE_TRIES = 50;

    /** Where groups can be made: the parent of each controller's group (one folder for v2). */
    record Place(boolean v2, Map<String, Path> parents) {
    }

    /** The totals one run is held to. */
    record Totals(long memoryBytes, int processes, boolean oneCore) {
    }

    private final Place place;
    private final Map<String, Path> groups;
    private final Totals totals;

    private Cgroup(Place place, Map<String, Path> groups, Totals totals) {
        this.place = place;
        this.groups = groups;
        this.totals = totals;
    }

    /** Where this process can make groups with memory and pids totals, or null when it cannot. */
    static Place find() {
        try {
            Map<String, String> paths = new LinkedHashMap<>();
            for (String line : Files.readAllLines(PROC_CGROUP)) {
                String[] fields = line.split(":", 3);
                if (fields.length == 3) {
                    for (String controller : fields[1].split(",")) {
                        paths.put(controller, fields[2]);
                    }
                }
            }
            Place v2 = unified(paths.get(""));
            return v2 != null ? v2 : legacy(paths);
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    private static Place unified(String path) throws IOException {
        Path mount = mountOf("cgroup2");
        if (path == null || mount == null) {
            return null;
        }
        Path parent = mount.resolve(path.substring(1));
        Path control = parent.resolve("cgroup.subtree_control");
        if (!Files.isWritable(parent) || !Files.isRegularFile(control)) {
            return null;
        }
        String enabled = Files.readString(control);
        if (!(enabled.contains("memory") && enabled.contains("pids"))) {
            try {
                Files.writeString(control, "+memory +pids");
            } catch (IOException e) {
                return null;   // not delegated, or this process is in the group (no internal processes)
            }
        }
        return new Place(true, Map.of("", parent));
    }

    private static Place legacy(Map<String, String> paths) throws IOException {
        Map<String, Path> parents = new LinkedHashMap<>();
        for (String controller : List.of("memory", "pids", "cpu")) {
            String path = paths.get(controller);
            Path mount = path == null ? null : mountOf(controller);
            Path parent = mount == null ? null : mount.resolve(path.substring(1));
            if (parent != null && Files.isDirectory(parent) && Files.isWritable(parent)) {
                parents.put(controller, parent);
            } else if (!controller.equals("cpu")) {
                return null;
            }
        }
        return new Place(false, parents);
    }

    /** The mount point of the cgroup file system of {@code type} ("cgroup2") or v1 {@code controller}. */
    private static Path mountOf(String typeOrController) throws IOException {
        for (String line : Files.readAllLines(MOUNTS)) {
            String[] halves = line.split(" - ", 2);
            if (halves.length < 2) {
                continue;
            }
            String[] mount = halves[0].split(" "), source = halves[1].split(" ");
            boolean v2 = source[0].equals("cgroup2");
            if (typeOrController.equals("cgroup2") ? v2 : source[0].equals("cgroup") && source.length > 2
                    && List.of(source[2].split(",")).contains(typeOrController)) {
                return Path.of(mount[4]);
            }
        }
        return null;
    }

    /** A new group in {@code place} held to {@code totals}. */
    static Cgroup create(Place place, Totals totals) throws IOException {
        Map<String, Path> groups = new LinkedHashMap<>();
        Cgroup cgroup = new Cgroup(place, groups, totals);
        try {
            for (int tries = 1; ; tries++) {
                try {
                    makeGroups(place, "tick1-" + ProcessHandle.current().pid() + "-" + NEXT.incrementAndGet(), groups);
                    break;
                } catch (FileAlreadyExistsException e) {
                    // A group left by an earlier process with this process id: take the next name.
                    cgroup.close();
                    groups.clear();
                    if (tries == NAME_TRIES) {
                        throw e;
                    }
                }
            }
            cgroup.limit();
        } catch (IOException | RuntimeException e) {
            cgroup.close();
            throw e instanceof IOException io ? io : new IOException(e);
        }
        return cgroup;
    }

    private static void makeGroups(Place place, String name, Map<String, Path> groups) throws IOException {
        for (Map.Entry<String, Path> parent : place.parents().entrySet()) {
            groups.put(parent.getKey(), Files.createDirectory(parent.getValue().resolve(name)));
        }
    }

    private void limit() throws IOException {
        long quota = totals.oneCore() ? CPU_PERIOD_MICROS : -1;
        if (place.v2()) {
            Path group = groups.get("");
            write(group, "memory.max", totals.memoryBytes());
            write(group, "memory.swap.max", 0);
            write(group, "pids.max", totals.processes());
            if (quota > 0 && Files.exists(group.resolve("cpu.max"))) {
                Files.writeString(group.resolve("cpu.max"), quota + " " + CPU_PERIOD_MICROS);
            }
            return;
        }
        Path memory = groups.get("memory");
        write(memory, "memory.limit_in_bytes", totals.memoryBytes());
        if (Files.exists(memory.resolve("memory.memsw.limit_in_bytes"))) {
            write(memory, "memory.memsw.limit_in_bytes", totals.memoryBytes());
        }
        write(groups.get("pids"), "pids.max", totals.processes());
        Path cpu = groups.get("cpu");
        if (cpu != null && quota > 0) {
            write(cpu, "cpu.cfs_period_us", CPU_PERIOD_MICROS);
            write(cpu, "cpu.cfs_quota_us", quota);
        }
    }

    private static void write(Path group, String file, long value) throws IOException {
        Path control = group.resolve(file);
        if (Files.exists(control)) {
            Files.writeString(control, Long.toString(value), StandardCharsets.US_ASCII);
        }
    }

    /**
     * The group's folders, one a controller (one for v2), for the shell that starts the run to move
     * itself into ({@link Sandbox#wrap}) before it becomes the run's first program.
     */
    List<Path> folders() {
        return List.copyOf(groups.values());
    }

    /**
     * The total the run reached, or null: the kernel's own counts of processes it killed for memory
     * and of forks it refused.
     */
    LimitReached limitReached() {
        Path memory = groups.get(place.v2() ? "" : "memory");
        Path pids = groups.get(place.v2() ? "" : "pids");
        if (count(memory, place.v2() ? "memory.events" : "memory.oom_control", "oom_kill") > 0) {
            return new LimitReached(NoImage.MEMORY_LIMIT, "the program used more than "
                    + RunLimits.size(totals.memoryBytes()) + " of memory in all (all its processes, and the files they "
                    + "kept in memory, together), and the kernel killed a process of it");
        }
        if (count(pids, "pids.events", "max") > 0) {
            return new LimitReached(NoImage.PROCESS_LIMIT,
                    "it reached the limit of " + totals.processes() + " processes and threads in all");
        }
        return null;
    }

    /** The number after {@code key} in a {@code key value} file of the group, or 0. */
    private static long count(Path group, String file, String key) {
        try {
            for (String line : Files.readAllLines(group.resolve(file))) {
                String[] fields = line.strip().split("\\s+");
                if (fields.length == 2 && fields[0].equals(key)) {
                    return Long.parseLong(fields[1]);
                }
            }
        } catch (IOException | RuntimeException e) {
            // No such count here.
        }
        return 0;
    }

    /**
     * Removes the groups; the run's processes have all ended by then. The kernel may still count
     * a process that has just been reaped (the pids and cpu controllers refuse to remove a group
     * until it is gone), so a refused removal is tried again for a few milliseconds.
     */
    @Override
    public void close() {
        for (Path group : groups.values()) {
            for (int tries = 1; ; tries++) {
                try {
                    Files.deleteIfExists(group);
                    break;
                } catch (IOException e) {
                    if (tries == REMOVE_TRIES) {
                        break;   // still busy: an empty group is small, and its name is never taken again
                    }
                    try {
                        Thread.sleep(1);
                    } catch (InterruptedException interrupted) {
                        Thread.currentThread().interrupt();
                        break;
                    }
                }
            }
        }
    }
}
