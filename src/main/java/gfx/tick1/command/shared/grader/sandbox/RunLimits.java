package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * What one run in the sandbox is held to per process: at most {@code cpuSeconds} of processor time
 * and {@code addressSpaceMiB} of address space, and, if {@code oneCore}, one processor core only;
 * with the limits every run has (file size, open files and, under a user of its own, processes).
 */
record RunLimits(int cpuSeconds, long addressSpaceMiB, boolean oneCore) {

    /** The descriptor bwrap reads the {@link SeccompFilter} from. */
    static final int FILTER_FD = 3;
    private static final Path SH = Path.of("/bin/sh");
    static final Path SETPRIV = Path.of("/usr/bin/setpriv");
    static final Path PRLIMIT = Path.of("/usr/bin/prlimit");
    private static final Path TASKSET = Path.of("/usr/bin/taskset");
    /** The most files the student's process may write, each at most this big (RLIMIT_FSIZE). */
    static final long FILE_SIZE_LIMIT = 64L << 20;
    private static final int OPEN_FILES_LIMIT = 256;
    /** Threads count as processes: the JVM's own, with room to spare, and the student's code's one. */
    static final int PROCESSES_LIMIT = 96;

    /**
     * The programs that hold a run to these limits before bwrap starts: its core ({@code taskset},
     * if {@code oneCore}, chosen by the {@code job}), its user ({@code setpriv}, when {@code uid} is
     * one of its own: not -1) and the limits per process ({@code prlimit}).
     */
    List<String> programs(int uid, int job) {
        List<String> limits = new ArrayList<>();
        String core = oneCore ? oneAllowedCore(job) : null;
        if (core != null) {
            limits.addAll(List.of(TASKSET.toString(), "--cpu-list", core));
        }
        if (uid >= 0) {
            limits.addAll(List.of(SETPRIV.toString(), "--reuid=" + uid, "--regid=" + uid, "--clear-groups",
                    "--inh-caps=-all", "--bounding-set=-all", "--no-new-privs"));
        }
        limits.addAll(List.of(PRLIMIT.toString(),
                "--cpu=" + cpuSeconds,
                "--as=" + (addressSpaceMiB << 20),
                "--fsize=" + FILE_SIZE_LIMIT,
                "--nofile=" + OPEN_FILES_LIMIT,
                "--core=0"));
        if (uid >= 0) {
            // RLIMIT_NPROC counts every process of the user: only meaningful for a user of its own.
            limits.add("--nproc=" + PROCESSES_LIMIT);
        }
        return limits;
    }

    /**
     * One of the cores this process may run on (from /proc/self/status), chosen by the process id
     * and the job so that grades running at the same time spread over the cores; null if that
     * cannot be told.
     */
    private static String oneAllowedCore(int job) {
        if (!Files.isExecutable(TASKSET)) {
            return null;
        }
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("Cpus_allowed_list:")) {
                    List<Integer> cores = new ArrayList<>();
                    for (String range : line.substring(line.indexOf(':') + 1).strip().split(",")) {
                        String[] ends = range.split("-");
                        int first = Integer.parseInt(ends[0]), last = Integer.parseInt(ends[ends.length - 1]);
                        for (int core = first; core <= last && cores.size() < 4096; core++) {
                            cores.add(core);
                        }
                    }
                    return cores.isEmpty() ? null
                            : Integer.toString(cores.get((int) ((ProcessHandle.current().pid() + job) % cores.size())));
                }
            }
        } catch (IOException | RuntimeException e) {
            // No pinning: the CPU-seconds limit still holds.
        }
        return null;
    }

    /**
     * The shell that starts the sandbox: it moves itself into the run's control group (when there
     * is one; it fails with status 125 rather than run outside it), opens the {@link SeccompFilter}
     * on descriptor {@value #FILTER_FD} for bwrap (the one way to hand bwrap a descriptor through
     * Java's ProcessBuilder), and becomes the run's first program: {@code filter}'s file, or null
     * for none. Empty when there is neither.
     */
    static List<String> startCommand(Cgroup cgroup, Path filter) {
        if (cgroup == null && filter == null) {
            return List.of();
        }
        List<String> command = new ArrayList<>(List.of(SH.toString(), "-c",
                "f=$1; shift; while [ \"$1\" != -- ]; do echo $$ > \"$1/cgroup.procs\" || exit 125; shift; done; "
                        + "shift; if [ -n \"$f\" ]; then exec \"$@\" " + FILTER_FD + "<\"$f\"; else exec \"$@\"; fi",
                "sh", filter == null ? "" : filter.toString()));
        if (cgroup != null) {
            cgroup.folders().forEach(group -> command.add(group.toString()));
        }
        command.add("--");
        return command;
    }

    /** A size for messages: "1 GiB", "768 MiB". */
    static String size(long bytes) {
        return bytes % (1L << 30) == 0 ? (bytes >> 30) + " GiB" : (bytes >> 20) + " MiB";
    }
}
