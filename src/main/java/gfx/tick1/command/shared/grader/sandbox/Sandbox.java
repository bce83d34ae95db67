package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Where {@code grade} runs the student's code: a bubblewrap sandbox (Debian's {@code bubblewrap}
 * package, the sandbox Flatpak uses). Inside it the student's process
 *
 * <ul>
 *   <li>runs as an unprivileged user of its own when {@code grade} runs as root (through
 *       {@code setpriv}), with no capabilities and no way to gain any;
 *   <li>sees of the host's files only the JDK and the libraries it loads ({@link SystemFiles}),
 *       read-only, each in memory when the run starts, the folders {@code grade} binds in
 *       (read-only but for its output folder, which is a file system of
 *       its own when {@code grade} runs as root, where nothing is mapped as code: {@link OutputDisk})
 *       and nothing else: no home folder, no {@code /tmp}, no shared memory ({@code /dev/shm} is an empty
 *       folder on a read-only {@code /dev}), no {@code /proc} (an empty folder),
 *       no other process, none of the organiser's scenes but its own;
 *   <li>has no network (a network namespace with nothing in it, not even the host's loopback),
 *       an empty environment, and a session and PID namespace of its own, so that it cannot
 *       type into the grader's terminal and everything it starts dies with it
 *       ({@code --die-with-parent});
 *   <li>starts no process, and makes no call that takes disk space a size does not show, under
 *       a seccomp filter ({@link SeccompFilter});
 *   <li>has limits ({@code prlimit}) on CPU seconds, address space, file size, open files and,
 *       under its own user, processes; the student's code runs on one core ({@code taskset}).
 * </ul>
 *
 * {@link #unconfined()} is {@code --no-sandbox}: the same command, none of the above.
 */
public final class Sandbox {

    /** The package that provides {@code bwrap}, for the message when it is missing. */
    public static final String PACKAGE = "bubblewrap";

    /**
     * Host programs the sandbox shows besides java, with the libraries they load: none in a grade.
     * The attack tests name those their attacks start (sh, fallocate, mkfifo, ...), so that what
     * holds the runs to their limits is tested against them too.
     */
    private static final String ALSO_SHOWN_PROPERTY = "tick1.grade.sandboxAlsoShows";
    /**
     * "true" lets the runs start processes, which a grade never does (see {@link SeccompFilter}): for
     * the tests whose attacks start the programs {@link #ALSO_SHOWN_PROPERTY} shows, so that what
     * holds the runs to their limits is tested against them.
     */
    private static final String PROCESSES_PROPERTY = "tick1.grade.sandboxAllowsProcesses";
    /** Debian's bwrap; the system property tick1.grade.bwrap names another (the tests name a missing one). */
    private static final String BWRAP_PROPERTY = "tick1.grade.bwrap";
    /** "host" keeps each run's output folder on the host's disk, as where no tmpfs can be mounted (for the tests). */
    private static final String OUTPUT_DISKS_PROPERTY = "tick1.grade.outputDisks";
    private static final Path SETPRIV = Path.of("/usr/bin/setpriv");
    private static final Path PRLIMIT = Path.of("/usr/bin/prlimit");
    private static final Path TASKSET = Path.of("/usr/bin/taskset");
    private static final Path SH = Path.of("/bin/sh");
    private static final Path TRUE = Path.of("/usr/bin/true");
    /** The descriptor bwrap reads the {@link SeccompFilter} from. */
    private static final int FILTER_FD = 3;

    /** The most files the student's process may write, each at most this big (RLIMIT_FSIZE). */
    static final long FILE_SIZE_LIMIT = 64L << 20;
    private static final int OPEN_FILES_LIMIT = 256;
    /** Threads count as processes: the JVM needs about 20; the student's code one. */
    static final int PROCESSES_LIMIT = 96;

    /** The first of the user ids the student's code runs as when the grader is root. */
    static final int FIRST_UID = 1_900_000_000;
    /**
     * Chooses each grader's user, far above the ranges of real users and of containers'
     * subordinate ids: at random, so that two grades at once almost never share one, and so that
     * the id, which the code can read, tells nothing of the machine (a user id made from the
     * grader's process id told a later grade how many processes an earlier one had started).
     */
    private static final java.security.SecureRandom RUN_USERS = new java.security.SecureRandom();

    /** A folder of the grader's, bound into the sandbox at {@code inside}, writable or not. */
    record Bind(Path outside, String inside, boolean writable) {
    }

    /** How many grades one program may run at once, each under a user of its own: see {@link #forJob}. */
    public static final int MOST_JOBS = 64;
    /** The distance between the user ids of two jobs: more than the process ids the first one's id is made of. */
    private static final int JOB_UID_STEP = 1_000_000;

    /** What this machine gives the sandbox: its bwrap, control groups, seccomp filter and output disks. */
    private final Host host;
    /** Whether there is a bwrap: false for {@link #unconfined()}. */
    private final boolean confined;
    /** The user the student's code runs as when the grader is root; -1 to keep the grader's. */
    private final int uid;
    /** Which of the grades this program runs at once this sandbox is for: 0 for a single grade. */
    private final int job;
    private Sandbox(Host host, int uid, int job) {
        this.host = host;
        this.confined = host.bwrap() != null;
        this.uid = uid;
        this.job = job;
    }

    /**
     * What this machine gives every sandbox made here: the bwrap (null for none), where control
     * groups are made (or null), the seccomp filter's file (or null), and whether each run's output
     * folder can be a file system of its own, the host's files the runs see (null for none), and
     * the stricter filter's file of the runs that render hidden scenes (null with no filter).
     */
    private record Host(Path bwrap, Cgroup.Place cgroups, Path seccompFilter, boolean ownDisks, SystemFiles system,
            Path hiddenRunFilter) {
    }

    /**
     * The same sandbox, after checking that it hides {@code paths} (the organiser's scenes and
     * their folder) from the runs, as it hides every file of the host's but the JDK and the
     * libraries it loads: the runs get their scenes only through the folder bound for them.
     *
     * @throws CannotHide when one is, holds or lies in what the runs see (the JDK, a library)
     */
    public Sandbox hiding(List<Path> paths) throws CannotHide {
        refuseWhatTheRunsSee(paths, host.system(), realPath(javaHome()) == null ? javaHome() : realPath(javaHome()));
        return this;
    }

    /**
     * The same sandbox for the {@code job}-th of the grades this program runs at the same time
     * (0 to {@link #MOST_JOBS} - 1): under a user of its own, so that one student's processes
     * never count against another's process limit nor can signal them, and started on the next core.
     */
    public Sandbox forJob(int job) {
        if (job < 0 || job >= MOST_JOBS) {
            throw new IllegalArgumentException("job " + job + ": must be from 0 to " + (MOST_JOBS - 1));
        }
        return new Sandbox(host, uid < 0 ? uid : uid + job * JOB_UID_STEP, job);
    }

    /**
     * The sandbox of this job's warm compiler: the same core, and a user of its own, so that the
     * compiler (which lives from one submission to the next) and the student's code never share a
     * process limit nor can signal each other. Only for a sandbox {@link #forJob} made.
     */
    public Sandbox forCompiler() {
        return new Sandbox(host, uid < 0 ? uid : uid + MOST_JOBS * JOB_UID_STEP, job);
    }

    /** No sandbox at all: the student's code runs as the grader, with the grader's files and network. */
    public static Sandbox unconfined() {
        return new Sandbox(new Host(null, null, null, false, null, null), -1, 0);
    }

    /**
     * The bubblewrap sandbox, after checking that it can be made here.
     *
     * @throws Unavailable when bubblewrap is missing or cannot create namespaces
     */
    public static Sandbox confined() throws Unavailable, InterruptedException {
        Path bwrap = Path.of(System.getProperty(BWRAP_PROPERTY, "/usr/bin/bwrap"));
        if (!Files.isExecutable(bwrap) || !Files.isExecutable(PRLIMIT)) {
            throw new Unavailable("bubblewrap is not installed");
        }
        boolean root;
        try {
            root = Integer.valueOf(0).equals(Files.getAttribute(Path.of("/proc/self"), "unix:uid"))
                    && Files.isExecutable(SETPRIV);
        } catch (IOException | UnsupportedOperationException e) {
            throw new Unavailable("cannot tell which user this is (" + e.getMessage() + ")");
        }
        Path seccompFilter;
        Path hiddenRunFilter;
        try {
            boolean processes = Boolean.getBoolean(PROCESSES_PROPERTY);
            seccompFilter = SeccompFilter.writeForThisMachine(false, processes);
            hiddenRunFilter = SeccompFilter.writeForThisMachine(true, processes);
        } catch (IOException e) {
            throw new Unavailable("cannot write the sandbox's seccomp filter (" + e.getMessage() + ")");
        }
        SystemFiles system;
        try {
            system = SystemFiles.of(javaHome(), java.util.Arrays.stream(
                    System.getProperty(ALSO_SHOWN_PROPERTY, "").split(java.io.File.pathSeparator))
                    .filter(name -> !name.isEmpty()).map(Path::of).toList());
        } catch (IOException e) {
            throw new Unavailable("cannot list the files of the JDK and the libraries java loads (" + e.getMessage()
                    + ")");
        }
        Host host = new Host(bwrap, Cgroup.find(), seccompFilter, root
                && !"host".equals(System.getProperty(OUTPUT_DISKS_PROPERTY)) && canMountOutputDisks(), system,
                hiddenRunFilter);
        Sandbox sandbox = new Sandbox(host,
                root ? FIRST_UID + RUN_USERS.nextInt(JOB_UID_STEP) : -1, 0);
        sandbox.selfTest();
        return sandbox;
    }

    /** Why the sandbox cannot be made. */
    public static final class Unavailable extends Exception {
        private static final long serialVersionUID = 1L;

        Unavailable(String reason) {
            super(reason);
        }
    }

    boolean isConfined() {
        return confined;
    }

    /** The user the student's code runs as; -1 for the grader's own. */
    int runUser() {
        return uid;
    }

    /** What this sandbox holds the code to: results graded under other rules are graded again. */
    public Enforcement enforcement() {
        return new Enforcement(confined, uid >= 0, confined && host.cgroups() != null,
                confined && host.seccompFilter() != null, confined && host.ownDisks());
    }

    /**
     * Null when each run is held to totals by a control group of its own; else the one line that
     * says they are not (the limits are then per process only).
     */
    public String totalsNotEnforced() {
        return !confined || host.cgroups() != null ? null
                : "no control group can be made here (cgroup v2 not delegated, cgroup v1 memory and pids not "
                        + "writable): the limits are per process; memory, processes and CPU are not limited in all";
    }

    /**
     * Null when the sandbox refuses the calls that reserve disk space a size does not show and those
     * that drop pages from the host's page cache ({@link SeccompFilter}); else the one line that says
     * it does not, on this machine.
     */
    public String callsNotRefused() {
        return !confined || host.seccompFilter() != null ? null
                : "tick1 has no seccomp filter for this machine (" + System.getProperty("os.arch") + "): disk space "
                        + "the code reserves with fallocate is not counted in its output folder's limit, and a run "
                        + "can drop the JDK's files from the page cache while another run going at the same time "
                        + "times its reads";
    }

    /**
     * Null when each run's output folder is a file system of its own whose size and number of
     * files the kernel enforces; else the one line that says it is not.
     */
    public String diskNotEnforced() {
        return !confined || host.ownDisks() ? null
                : (uid < 0 ? "grading as a normal user" : "no file system can be mounted here")
                        + ": the output folder of each run is on the host's disk, held to its limit by a count of "
                        + "its files' names, which misses files the code deletes while it holds them open, and the "
                        + "code can load what it writes there as machine code; a cohort's "
                        + "compiler writes its class files there too, counted only once it has compiled";
    }

    /**
     * The file system of one run's output folder {@code folder}, an empty folder this sandbox has
     * {@link #share shared} for writing: a tmpfs of its own where the sandbox can mount one (close
     * it once the folder is read), else the folder as it is.
     */
    OutputDisk outputDisk(Path folder) throws IOException {
        return host.ownDisks() ? OutputDisk.mount(folder, uid) : OutputDisk.onHostDisk(folder);
    }

    /**
     * The file system of the warm compiler's folder {@code folder}, an empty folder, for a sandbox
     * {@link #forCompiler} made: a tmpfs of its own, the grader's and readable by the compiler's
     * user, where the sandbox can mount one (close it once the compiler has ended); else the folder.
     */
    OutputDisk compilerDisk(Path folder) throws IOException {
        return host.ownDisks() ? OutputDisk.mountReadable(folder, uid) : OutputDisk.onHostDisk(folder);
    }

    /** Whether this grader can mount each run a tmpfs of its own: it mounts one, in a new temporary folder. */
    private static boolean canMountOutputDisks() {
        try {
            Path scratch = Files.createTempDirectory("tick1-mount-");
            try {
                return OutputDisk.canMount(scratch);
            } finally {
                Files.deleteIfExists(scratch);
            }
        } catch (IOException e) {
            return false;
        }
    }

    /** A control group for one run held to {@code totals}, or null when none can be made. */
    Cgroup cgroupFor(Cgroup.Totals totals) throws IOException {
        return confined && host.cgroups() != null ? Cgroup.create(host.cgroups(), totals) : null;
    }

    /** A size for messages: "1 GiB", "768 MiB". */
    static String size(long bytes) {
        return bytes % (1L << 30) == 0 ? (bytes >> 30) + " GiB" : (bytes >> 20) + " MiB";
    }

    /**
     * Checks that the user the student's code runs as can reach {@code folder} (bubblewrap opens
     * the folders it binds as that user): every folder above it must let others through.
     *
     * @throws IOException saying which folder does not, and what to do
     */
    public void checkReachable(Path folder) throws IOException {
        if (uid < 0) {
            return;
        }
        for (Path above = folder.toAbsolutePath().getParent(); above != null; above = above.getParent()) {
            Object mode = Files.getAttribute(above, "unix:mode");
            if (mode instanceof Integer bits && (bits & 01) == 0) {
                throw new IOException(above + ": the sandbox's user cannot pass through this folder to the work "
                        + "folder; grade with a temporary folder it can reach (JAVA_OPTS=-Djava.io.tmpdir=/tmp)");
            }
        }
    }

    /**
     * Reads into memory every file of the host's that a run sees ({@link SystemFiles#warm}) and
     * every file of the folders {@code binds} shows it read-only, before the run starts: whatever
     * pages of them an earlier run read or dropped, all are in memory when this one times them.
     */
    void warm(List<Bind> binds) {
        if (!confined) {
            return;
        }
        host.system().warm(binds.stream().filter(bind -> !bind.writable()).map(Bind::outside).toList());
    }

    /**
     * Makes {@code folder} readable (or, if {@code writable}, owned) by the user the student's code
     * runs as, and no one else. Does nothing when that user is the grader.
     */
    public void share(Path folder, boolean writable) throws IOException {
        if (uid < 0) {
            return;
        }
        try (var files = Files.walk(folder)) {
            for (Path file : files.toList()) {
                if (writable) {
                    Files.setAttribute(file, "unix:uid", uid);
                }
                Files.setAttribute(file, "unix:gid", uid);
                Files.setAttribute(file, "unix:mode", Files.isDirectory(file) ? 0750 : 0640);
            }
        }
    }

    /**
     * The command that runs {@code command} inside the sandbox, with {@code binds}, at most
     * {@code cpuSeconds} of processor time and {@code addressSpaceMiB} of address space, and, if
     * {@code oneCore}, on one processor core only; with {@code hiddenScenes}, under the hidden runs' stricter
     * seccomp filter.
     */
    List<String> wrap(List<String> command, List<Bind> binds, int cpuSeconds, long addressSpaceMiB, boolean oneCore,
            Cgroup cgroup, boolean hiddenScenes) {
        if (!confined) {
            return command;
        }
        List<String> wrapped = new ArrayList<>(startCommand(cgroup,
                hiddenScenes ? host.hiddenRunFilter() : host.seccompFilter()));
        wrapped.addAll(limits(cpuSeconds, addressSpaceMiB, oneCore));
        wrapped.addAll(List.of("--", host.bwrap().toString(),
                "--unshare-all", "--unshare-user", "--disable-userns",
                "--die-with-parent", "--new-session", "--cap-drop", "ALL",
                "--clearenv", "--setenv", "PATH", "/usr/bin", "--setenv", "LANG", "C.UTF-8",
                "--setenv", "MALLOC_ARENA_MAX", "2"));
        if (host.seccompFilter() != null) {
            wrapped.addAll(List.of("--seccomp", Integer.toString(FILTER_FD)));
        }
        // Of the host's files, the JDK and the libraries it loads, each on its own: no folder of the host's,
        // so neither tick1, nor the grader's temporary folder, nor any scene of the organiser's.
        wrapped.addAll(host.system().bwrapArguments());
        // No file system a run can write but its output folder, which is sized and, as root, noexec: / and /dev
        // (bwrap's own, of half the host's memory) are read-only, and /dev/shm is an empty folder on that /dev.
        // No /proc at all. It numbers a process's files, as they are first looked at, from the count the kernel
        // numbers pipes and sockets by, one for the whole machine, so a run that looked at many could leave a
        // number for a later run to read; its files count what the whole machine did (stat, meminfo, pressure);
        // and a process may write its own memory through /proc/self/mem, code included, which would bring
        // native code into a run in Java alone. Without /proc the loader cannot find the launcher's libraries
        // from where java is ($ORIGIN), so it is told.
        wrapped.addAll(List.of("--dir", "/proc", "--setenv", "LD_LIBRARY_PATH", javaHome().resolve("lib").toString(),
                "--dev", "/dev", "--remount-ro", "/dev"));
        for (Bind bind : binds) {
            wrapped.addAll(List.of(bind.writable() ? "--bind" : "--ro-bind", bind.outside().toString(), bind.inside()));
        }
        wrapped.addAll(List.of("--remount-ro", "/", "--chdir", "/", "--"));
        wrapped.addAll(command);
        return wrapped;
    }

    /**
     * The programs that hold the sandbox to its limits before bwrap starts: its core ({@code taskset},
     * if {@code oneCore}), its user ({@code setpriv}, when the grader is root) and the limits per
     * process ({@code prlimit}).
     */
    private List<String> limits(int cpuSeconds, long addressSpaceMiB, boolean oneCore) {
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
     * The shell that starts the sandbox: it moves itself into the run's control group (when there
     * is one; it fails with status 125 rather than run outside it), opens the {@link SeccompFilter}
     * on descriptor {@value #FILTER_FD} for bwrap (the one way to hand bwrap a descriptor through
     * Java's ProcessBuilder), and becomes the run's first program: {@code filter}'s file, or null
     * for none. Empty when there is neither.
     */
    private List<String> startCommand(Cgroup cgroup, Path filter) {
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

    /** The JDK this program runs on, whose java the runs start. */
    private static Path javaHome() {
        return Path.of(System.getProperty("java.home")).toAbsolutePath();
    }

    /** The real path of {@code path}; null when it cannot be read (not there: nothing to hide). */
    private static Path realPath(Path path) {
        try {
            return path.toRealPath();
        } catch (IOException e) {
            return null;
        }
    }

    /**
     * Refuses a secret the runs would see: one in the JDK {@code jdk} (its real path) or holding
     * it, or one that is, or is a folder that holds, one of {@code system}'s files or links (none
     * for a sandbox that shows the host's files as they are). Hiding it would take from the runs
     * what they need. A secret that cannot be read is not there to hide.
     */
    static void refuseWhatTheRunsSee(List<Path> secrets, SystemFiles system, Path jdk) throws CannotHide {
        List<Path> seen = new ArrayList<>(List.of(jdk));
        if (system != null) {
            seen.addAll(system.files());
            seen.addAll(system.pathsSeen());
        }
        for (Path secret : secrets) {
            Path real = realPath(secret);
            if (real == null) {
                continue;
            }
            boolean folder = Files.isDirectory(real);
            Path needed = real.startsWith(jdk) ? jdk
                    : seen.stream().filter(path -> path.startsWith(real)).findFirst().orElse(null);
            if (needed != null) {
                throw new CannotHide(secret + ": the runs need " + needed + ", so tick1 cannot hide "
                        + (folder ? "this folder's scenes" : "this scene") + " from the student's code without "
                        + "stopping every run: give the scenes a folder of their own");
            }
        }
    }

    /** Why the sandbox cannot hide the organiser's scenes: in one line for the organiser. */
    public static final class CannotHide extends IOException {
        private static final long serialVersionUID = 1L;

        CannotHide(String reason) {
            super(reason);
        }
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
     * A process for {@link #wrap}'s command, started with an environment of PATH alone. bwrap's
     * {@code --clearenv} empties the environment of the command it runs, but not its own: and
     * bwrap's first process inside the sandbox runs as the student's user, whose memory holds it
     * (and a process of the same user may read another's). So the grader's environment (tokens, paths, names) must
     * never reach bwrap, nor taskset, setpriv and prlimit before it.
     */
    static ProcessBuilder processFor(List<String> wrappedCommand) {
        ProcessBuilder builder = new ProcessBuilder(wrappedCommand);
        builder.environment().clear();
        builder.environment().put("PATH", "/usr/bin:/bin");
        return builder;
    }

    /**
     * A process for {@link #wrap}'s command in this sandbox: as {@link #processFor} makes one; or,
     * with no sandbox, in the grader's environment (the code is the user's own, and on Windows Java
     * needs some of it, SystemRoot among them) but for the variables that would give the harness's
     * JVM options of their own and so change its limits.
     */
    ProcessBuilder process(List<String> wrappedCommand) {
        if (confined) {
            return processFor(wrappedCommand);
        }
        ProcessBuilder builder = new ProcessBuilder(wrappedCommand);
        builder.environment().keySet().removeAll(List.of("JAVA_TOOL_OPTIONS", "_JAVA_OPTIONS", "JDK_JAVA_OPTIONS"));
        return builder;
    }

    /**
     * What a control group adds to one run in the sandbox, in seconds: the median of {@code runs}
     * times making, limiting and removing one, plus the median extra time of starting a program
     * through the shell that joins it; NaN where no group can be made. (The kernel's accounting
     * while the code runs is not in it. Whole sandbox runs with and without a group differ by
     * less than their own noise on a shared machine, so the parts are timed.)
     */
    public double cgroupSeconds(int runs) throws IOException, InterruptedException {
        if (!confined || host.cgroups() == null) {
            return Double.NaN;
        }
        long[] group = new long[runs], shell = new long[runs];
        for (int i = 0; i < runs; i++) {
            long start = System.nanoTime();
            cgroupFor(new Cgroup.Totals(256L << 20, PROCESSES_LIMIT, true)).close();
            group[i] = System.nanoTime() - start;
            shell[i] = timeStart("/bin/sh", "-c", "exec /usr/bin/true") - timeStart("/usr/bin/true");
        }
        return (median(group) + median(shell)) / 1e9;
    }

    /**
     * What its own output file system adds to one run in the sandbox, in seconds: the median of
     * {@code runs} times mounting one, counting it once as a run's end does, and unmounting it; NaN
     * where the runs' output folders are on the host's disk.
     */
    public double outputDiskSeconds(int runs) throws IOException {
        if (!confined || !host.ownDisks()) {
            return Double.NaN;
        }
        Path folder = Files.createTempDirectory("tick1-disk-");
        try {
            long[] times = new long[runs];
            for (int i = 0; i < runs; i++) {
                long start = System.nanoTime();
                try (OutputDisk disk = outputDisk(folder)) {
                    disk.overCap();
                }
                times[i] = System.nanoTime() - start;
            }
            return median(times) / 1e9;
        } finally {
            WorkFolder.delete(folder);
        }
    }

    /**
     * What showing a run the host's files one by one ({@link SystemFiles}) adds to it, in seconds:
     * reading them into memory before it ({@link #warm}), and starting bwrap with each bound on its
     * own rather than all of /usr bound at once (each start runs {@code true}, without limits); the
     * medians of {@code runs} times each. NaN without a sandbox.
     */
    public double systemFilesSeconds(int runs) throws IOException, InterruptedException {
        if (!confined) {
            return Double.NaN;
        }
        List<String> start = List.of(host.bwrap().toString(), "--unshare-all", "--die-with-parent", "--proc", "/proc",
                "--dev", "/dev");
        List<String> eachFile = new ArrayList<>(start);
        eachFile.addAll(host.system().bwrapArguments());
        eachFile.addAll(List.of("--ro-bind", TRUE.toString(), TRUE.toString(), "--", TRUE.toString()));
        List<String> allOfUsr = new ArrayList<>(start);
        allOfUsr.addAll(List.of("--ro-bind", "/usr", "/usr", "--symlink", "usr/lib", "/lib", "--symlink", "usr/lib64",
                "/lib64", "--", TRUE.toString()));
        long[] warming = new long[runs], filesStart = new long[runs], usrStart = new long[runs];
        for (int i = 0; i < runs; i++) {
            long before = System.nanoTime();
            warm(List.of());
            warming[i] = System.nanoTime() - before;
            filesStart[i] = timeStart(eachFile.toArray(String[]::new));
            usrStart[i] = timeStart(allOfUsr.toArray(String[]::new));
        }
        return (median(warming) + median(filesStart) - median(usrStart)) / 1e9;
    }

    private static long timeStart(String... command) throws IOException, InterruptedException {
        long start = System.nanoTime();
        Process process = processFor(List.of(command)).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        process.getOutputStream().close();
        process.waitFor();
        return System.nanoTime() - start;
    }

    private static double median(long[] values) {
        long[] sorted = values.clone();
        java.util.Arrays.sort(sorted);
        int middle = sorted.length / 2;
        return sorted.length % 2 == 1 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2.0;
    }

    /**
     * Runs {@code true} in the sandbox, bound in for this run alone (it loads only libraries java
     * loads too): bubblewrap may be installed where namespaces are not allowed.
     */
    private void selfTest() throws Unavailable, InterruptedException {
        try {
            Process process = processFor(wrap(List.of(TRUE.toString()),
                    List.of(new Bind(TRUE, TRUE.toString(), false)), 5, 256, false, null, false))
                    .redirectErrorStream(true).start();
            process.getOutputStream().close();
            byte[] said = process.getInputStream().readNBytes(4096);
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                throw new Unavailable("bubblewrap did not start");
            }
            if (process.exitValue() != 0) {
                String why = ChildOutput.printable(new String(said, java.nio.charset.StandardCharsets.UTF_8)).strip();
                throw new Unavailable("bubblewrap cannot create a sandbox here"
                        + (why.isEmpty() ? "" : " (" + why.lines().findFirst().orElse("") + ")"));
            }
        } catch (IOException e) {
            throw new Unavailable("bubblewrap cannot be started: " + e.getMessage());
        }
    }
}
