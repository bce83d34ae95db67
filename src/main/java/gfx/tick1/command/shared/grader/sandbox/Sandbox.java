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
 *   <li>sees a read-only system ({@code /usr} and the JDK's configuration), the folders
 *       {@code grade} binds in (read-only but for its output folder, which is a file system of
 *       its own when {@code grade} runs as root: {@link OutputDisk}) and nothing else: no home
 *       folder, no {@code /tmp}, no other process, none of the organiser's scenes but its own;
 *   <li>has no network (a network namespace with nothing in it, not even the host's loopback),
 *       an empty environment, and a session and PID namespace of its own, so that it cannot
 *       type into the grader's terminal and everything it starts dies with it
 *       ({@code --die-with-parent});
 *   <li>has limits ({@code prlimit}) on CPU seconds, address space, file size, open files and,
 *       under its own user, processes; the student's code runs on one core ({@code taskset}).
 * </ul>
 *
 * {@link #unconfined()} is {@code --no-sandbox}: the same command, none of the above.
 */
public final class Sandbox {

    /** The package that provides {@code bwrap}, for the message when it is missing. */
    public static final String PACKAGE = "bubblewrap";

    /** Debian's bwrap; the system property tick1.grade.bwrap names another (the tests name a missing one). */
    private static final String BWRAP_PROPERTY = "tick1.grade.bwrap";
    /** "host" keeps each run's output folder on the host's disk, as where no tmpfs can be mounted (for the tests). */
    private static final String OUTPUT_DISKS_PROPERTY = "tick1.grade.outputDisks";
    private static final Path SETPRIV = Path.of("/usr/bin/setpriv");
    private static final Path PRLIMIT = Path.of("/usr/bin/prlimit");
    private static final Path TASKSET = Path.of("/usr/bin/taskset");
    private static final Path SH = Path.of("/bin/sh");
    /** The descriptor bwrap reads the {@link SpaceFilter} from. */
    private static final int FILTER_FD = 3;
    /** The JDK's configuration files, which java.home links to on Debian. */
    private static final Path JAVA_CONFIG = Path.of("/etc/java-17-openjdk");

    /** The most files the student's process may write, each at most this big (RLIMIT_FSIZE). */
    static final long FILE_SIZE_LIMIT = 64L << 20;
    private static final int OPEN_FILES_LIMIT = 256;
    /** Threads count as processes: the JVM needs about 20; the student's code one. */
    static final int PROCESSES_LIMIT = 96;

    /** The first of the user ids the student's code runs as when the grader is root. */
    static final int FIRST_UID = 1_900_000_000;

    /** A folder of the grader's, bound into the sandbox at {@code inside}, writable or not. */
    record Bind(Path outside, String inside, boolean writable) {
    }

    /** How many grades one program may run at once, each under a user of its own: see {@link #forJob}. */
    public static final int MOST_JOBS = 64;
    /** The distance between the user ids of two jobs: more than the process ids the first one's id is made of. */
    private static final int JOB_UID_STEP = 1_000_000;

    /** The size of the sandbox's shared memory, /dev/shm (its / and /dev are read-only). */
    static final long SHM_BYTES = 64L << 20;
    /** The size of each empty folder that hides tick1's own code under /usr. */
    private static final long HIDING_BYTES = 64L << 10;

    /** What this machine gives the sandbox: its bwrap, control groups, seccomp filter and output disks. */
    private final Host host;
    /** Whether there is a bwrap: false for {@link #unconfined()}. */
    private final boolean confined;
    /** The user the student's code runs as when the grader is root; -1 to keep the grader's. */
    private final int uid;
    /** Which of the grades this program runs at once this sandbox is for: 0 for a single grade. */
    private final int job;
    /** Folders of the grader's to hide wherever the sandbox would show them: the organiser's scenes. */
    private final List<Path> secrets;

    private Sandbox(Host host, int uid, int job, List<Path> secrets) {
        this.host = host;
        this.confined = host.bwrap() != null;
        this.uid = uid;
        this.job = job;
        this.secrets = List.copyOf(secrets);
    }

    /**
     * What this machine gives every sandbox made here: the bwrap (null for none), where control
     * groups are made (or null), the seccomp filter's file (or null), and whether each run's output
     * folder can be a file system of its own.
     */
    private record Host(Path bwrap, Cgroup.Place cgroups, Path spaceFilter, boolean ownDisks) {
    }

    /**
     * The same sandbox, which also hides {@code paths} (the organiser's scenes and their folder),
     * should their real paths lie in what it shows (/usr, the JDK's folders): a folder under an
     * empty folder, a file under an empty file. The runs get their scenes only through the folder
     * bound for them, never through a path of the grader's.
     *
     * @throws CannotHide when one is a folder that holds what the sandbox shows or the runs need,
     *     or lies in the JDK the runs use, or a file with another name (a hard link)
     */
    public Sandbox hiding(List<Path> paths) throws CannotHide {
        List<Path> all = new ArrayList<>(secrets);
        all.addAll(paths);
        secretsShown(shown(), all);
        noneNeeded(all);
        noOtherNames(all);
        return new Sandbox(host, uid, job, all);
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
        return new Sandbox(host, uid < 0 ? uid : uid + job * JOB_UID_STEP, job, secrets);
    }

    /**
     * The sandbox of this job's warm compiler: the same core, and a user of its own, so that the
     * compiler (which lives from one submission to the next) and the student's code never share a
     * process limit nor can signal each other. Only for a sandbox {@link #forJob} made.
     */
    public Sandbox forCompiler() {
        return new Sandbox(host, uid < 0 ? uid : uid + MOST_JOBS * JOB_UID_STEP, job, secrets);
    }

    /** No sandbox at all: the student's code runs as the grader, with the grader's files and network. */
    public static Sandbox unconfined() {
        return new Sandbox(new Host(null, null, null, false), -1, 0, List.of());
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
        // A user of its own for each grade running at the same time (the grader's process id is
        // unique), far above the ranges of real users and of containers' subordinate ids.
        Path spaceFilter;
        try {
            spaceFilter = SpaceFilter.writeForThisMachine();
        } catch (IOException e) {
            throw new Unavailable("cannot write the sandbox's seccomp filter (" + e.getMessage() + ")");
        }
        Sandbox sandbox = new Sandbox(new Host(bwrap, Cgroup.find(), spaceFilter, root
                && !"host".equals(System.getProperty(OUTPUT_DISKS_PROPERTY)) && canMountOutputDisks()),
                root ? FIRST_UID + (int) (ProcessHandle.current().pid() % JOB_UID_STEP) : -1, 0, List.of());
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

    /** What this sandbox holds the code to: results graded under other rules are graded again. */
    public Enforcement enforcement() {
        return new Enforcement(confined, uid >= 0, confined && host.cgroups() != null,
                confined && host.spaceFilter() != null, confined && host.ownDisks());
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
     * Null when the sandbox refuses the calls that reserve disk space a size does not show
     * ({@link SpaceFilter}); else the one line that says it does not, on this machine.
     */
    public String reservationsNotRefused() {
        return !confined || host.spaceFilter() != null ? null
                : "tick1 has no seccomp filter for this machine (" + System.getProperty("os.arch") + "): disk space "
                        + "the code reserves with fallocate is not counted in its output folder's limit";
    }

    /**
     * Null when each run's output folder is a file system of its own whose size and number of
     * files the kernel enforces; else the one line that says it is not.
     */
    public String diskNotEnforced() {
        return !confined || host.ownDisks() ? null
                : (uid < 0 ? "grading as a normal user" : "no file system can be mounted here")
                        + ": the output folder of each run is on the host's disk, held to its limit by a count of "
                        + "its files' names, which misses files the code deletes while it holds them open; a cohort's "
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
     * {@code oneCore}, on one processor core only.
     */
    List<String> wrap(List<String> command, List<Bind> binds, int cpuSeconds, long addressSpaceMiB, boolean oneCore,
            Cgroup cgroup) throws CannotHide {
        if (!confined) {
            return command;
        }
        List<String> wrapped = new ArrayList<>(startCommand(cgroup));
        wrapped.addAll(limits(cpuSeconds, addressSpaceMiB, oneCore));
        wrapped.addAll(List.of("--", host.bwrap().toString(),
                "--unshare-all", "--unshare-user", "--disable-userns",
                "--die-with-parent", "--new-session", "--cap-drop", "ALL",
                "--clearenv", "--setenv", "PATH", "/usr/bin", "--setenv", "LANG", "C.UTF-8",
                "--setenv", "MALLOC_ARENA_MAX", "2",
                "--ro-bind", "/usr", "/usr",
                "--symlink", "usr/bin", "/bin", "--symlink", "usr/lib", "/lib", "--symlink", "usr/lib64", "/lib64"));
        if (host.spaceFilter() != null) {
            wrapped.addAll(List.of("--seccomp", Integer.toString(FILTER_FD)));
        }
        if (Files.isDirectory(JAVA_CONFIG)) {
            wrapped.addAll(List.of("--ro-bind", JAVA_CONFIG.toString(), JAVA_CONFIG.toString()));
        }
        Path javaHome = javaHome();
        if (!javaHome.startsWith("/usr")) {
            wrapped.addAll(List.of("--ro-bind", javaHome.toString(), javaHome.toString()));
        }
        // tick1 itself and the grader's temporary folder (every work folder, with the hidden scenes each
        // job copies) may lie in what is shown: hide them, so that there is no renderer to copy and no
        // scene to read but those bound in for the run.
        List<Path> hide = new ArrayList<>(ownCode());
        hide.add(Path.of(System.getProperty("java.io.tmpdir")));
        List<Path> hidden = new ArrayList<>();
        for (Path system : shown()) {
            for (Path folder : foldersUnder(system, hide)) {
                wrapped.addAll(List.of("--size", Long.toString(HIDING_BYTES), "--tmpfs", folder.toString()));
                hidden.add(folder);
            }
        }
        // The organiser's scenes, each file and folder by its real path, wherever in what is shown.
        for (Secret secret : secretsShown(shown(), secrets)) {
            if (hidden.stream().anyMatch(secret.path()::startsWith)) {
                continue;
            }
            if (secret.folder()) {
                wrapped.addAll(List.of("--size", Long.toString(HIDING_BYTES), "--tmpfs", secret.path().toString()));
                hidden.add(secret.path());
            } else {
                wrapped.addAll(List.of("--ro-bind", "/dev/null", secret.path().toString()));
            }
        }
        // Every tmpfs has a size, and / and /dev (bwrap's own, of half the host's memory) are read-only.
        wrapped.addAll(List.of("--proc", "/proc", "--dev", "/dev",
                "--size", Long.toString(SHM_BYTES), "--perms", "1777", "--tmpfs", "/dev/shm",
                "--remount-ro", "/dev"));
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
     * is one; it fails with status 125 rather than run outside it), opens the {@link SpaceFilter}
     * on descriptor {@value #FILTER_FD} for bwrap (the one way to hand bwrap a descriptor through
     * Java's ProcessBuilder), and becomes the run's first program. Empty when there is neither.
     */
    private List<String> startCommand(Cgroup cgroup) {
        if (cgroup == null && host.spaceFilter() == null) {
            return List.of();
        }
        List<String> command = new ArrayList<>(List.of(SH.toString(), "-c",
                "f=$1; shift; while [ \"$1\" != -- ]; do echo $$ > \"$1/cgroup.procs\" || exit 125; shift; done; "
                        + "shift; if [ -n \"$f\" ]; then exec \"$@\" " + FILTER_FD + "<\"$f\"; else exec \"$@\"; fi",
                "sh", host.spaceFilter() == null ? "" : host.spaceFilter().toString()));
        if (cgroup != null) {
            cgroup.folders().forEach(group -> command.add(group.toString()));
        }
        command.add("--");
        return command;
    }

    /** Where this program's own classes and libraries are: its class path and its own jar or folder. */
    private static List<Path> ownCode() {
        List<Path> code = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path", "").split(java.io.File.pathSeparator)) {
            if (!entry.isEmpty()) {
                code.add(Path.of(entry));
            }
        }
        try {
            code.add(Path.of(Sandbox.class.getProtectionDomain().getCodeSource().getLocation().toURI()));
        } catch (java.net.URISyntaxException | RuntimeException e) {
            // The class path above is all there is to hide.
        }
        return code;
    }

    /** The JDK this program runs on, which the sandbox shows for the harness's JVM. */
    private static Path javaHome() {
        return Path.of(System.getProperty("java.home")).toAbsolutePath();
    }

    /** The host's folders the sandbox shows, read-only: /usr, the JDK's configuration, the JDK if elsewhere. */
    private static List<Path> shown() {
        List<Path> shown = new ArrayList<>(List.of(Path.of("/usr")));
        if (Files.isDirectory(JAVA_CONFIG)) {
            shown.add(JAVA_CONFIG);
        }
        if (!javaHome().startsWith("/usr")) {
            shown.add(javaHome());
        }
        return shown;
    }

    /**
     * What the runs need from the host besides what {@link #shown()} names: the JDK (by its path and
     * its real path), the programs and libraries (/usr/bin, /usr/lib, ... and the links to them
     * that lead there), and /etc.
     */
    private static List<Path> needed() {
        List<Path> needed = new ArrayList<>(shown());
        needed.add(javaHome());
        for (String system : List.of("/usr/bin", "/usr/sbin", "/usr/lib", "/usr/lib32", "/usr/lib64", "/usr/libx32",
                "/usr/libexec", "/usr/share", "/bin", "/lib", "/lib64", "/etc")) {
            needed.add(Path.of(system));
        }
        needed.addAll(needed.stream().map(Sandbox::realPath).filter(java.util.Objects::nonNull).toList());
        return needed;
    }

    /** The real path of {@code path}; null when it cannot be read (not there: nothing to hide or need). */
    private static Path realPath(Path path) {
        try {
            return path.toRealPath();
        } catch (IOException e) {
            return null;
        }
    }

    /**
     * Refuses a secret whose hiding would take from the runs what they need: a folder that holds
     * one of {@link #needed()}, a folder inside one of the system's folders the runs load from
     * (its libraries, say, which an empty folder would replace), or anything in the JDK the runs use
     * (hidden, the runs have no java).
     */
    private static void noneNeeded(List<Path> secrets) throws CannotHide {
        List<Path> needed = needed();
        List<Path> shown = shown();
        List<Path> systemFolders = needed.stream().filter(path -> !shown.contains(path)).toList();
        Path jdk = realPath(javaHome()) == null ? javaHome() : realPath(javaHome());
        for (Path secret : secrets) {
            Path real = realPath(secret);
            if (real == null) {
                continue;
            }
            Path refused = real.startsWith(jdk) ? jdk : null;
            for (Path system : needed) {
                if (refused == null && (system.startsWith(real)
                        || Files.isDirectory(real) && systemFolders.contains(system) && real.startsWith(system))) {
                    refused = system;
                }
            }
            if (refused != null) {
                throw new CannotHide(secret + ": the runs need " + refused
                        + ", so tick1 cannot hide this folder's scenes from the student's code without "
                        + "stopping every run: give the scenes a folder of their own");
            }
        }
    }

    /**
     * Refuses a secret file with more than one name (a hard link): the sandbox hides by path, and
     * the other name, wherever it is, would still show the scene to the student's code.
     */
    private static void noOtherNames(List<Path> secrets) throws CannotHide {
        for (Path secret : secrets) {
            Path real = realPath(secret);
            if (real == null || !Files.isRegularFile(real)) {
                continue;
            }
            int names;
            try {
                names = (Integer) Files.getAttribute(real, "unix:nlink");
            } catch (IOException | UnsupportedOperationException e) {
                throw new CannotHide(secret + ": tick1 cannot tell whether this scene has another name it cannot hide ("
                        + e.getMessage() + "): copy it to a file of its own");
            }
            if (names > 1) {
                throw new CannotHide(secret + ": this scene has " + (names - 1) + " other name(s) (hard links) that "
                        + "tick1 cannot hide from the student's code: copy it to a file of its own");
            }
        }
    }

    /** One of the organiser's scenes, or their folder, by its real path: hidden under an empty folder or file. */
    record Secret(Path path, boolean folder) {
    }

    /**
     * The real paths of {@code secrets} (files and folders, or links to them) that lie in one of
     * {@code shown}, the folders the sandbox shows, the folders before the files. A secret that
     * cannot be read is not there to hide.
     *
     * @throws CannotHide for a folder that is one of {@code shown} or holds one: hiding it would hide
     *     what the runs need
     */
    static List<Secret> secretsShown(List<Path> shown, List<Path> secrets) throws CannotHide {
        List<Secret> folders = new ArrayList<>(), files = new ArrayList<>();
        for (Path secret : secrets) {
            Path real = realPath(secret);
            if (real == null) {
                continue;
            }
            boolean folder = Files.isDirectory(real);
            for (Path system : shown) {
                if (folder && system.startsWith(real)) {
                    throw new CannotHide(secret + ": the sandbox shows the student's code what is in " + system
                            + ", so it cannot hide this folder's scenes from it: give the scenes a folder of "
                            + "their own");
                }
            }
            if (shown.stream().anyMatch(real::startsWith)) {
                (folder ? folders : files).add(new Secret(real, folder));
            }
        }
        folders.addAll(files);
        return folders;
    }

    /** Why the sandbox cannot hide the organiser's scenes: in one line for the organiser. */
    public static final class CannotHide extends IOException {
        private static final long serialVersionUID = 1L;

        CannotHide(String reason) {
            super(reason);
        }
    }

    /**
     * The folders holding {@code code} (files such as jars: the folder they are in; folders:
     * themselves) that lie inside {@code system}, a part of the file system the sandbox shows.
     */
    static List<Path> foldersUnder(Path system, List<Path> code) {
        List<Path> folders = new ArrayList<>();
        for (Path entry : code) {
            Path real;
            try {
                real = entry.toRealPath();
            } catch (IOException e) {
                continue;
            }
            Path folder = Files.isDirectory(real) ? real : real.getParent();
            if (folder != null && folder.startsWith(system) && !folder.equals(system) && !folders.contains(folder)) {
                folders.add(folder);
            }
        }
        return folders;
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
     * bwrap's first process inside the sandbox runs as the student's user, where
     * {@code /proc/1/environ} shows it. So the grader's environment (tokens, paths, names) must
     * never reach bwrap, nor taskset, setpriv and prlimit before it.
     */
    static ProcessBuilder processFor(List<String> wrappedCommand) {
        ProcessBuilder builder = new ProcessBuilder(wrappedCommand);
        builder.environment().clear();
        builder.environment().put("PATH", "/usr/bin:/bin");
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

    /** Runs {@code true} in the sandbox: bubblewrap may be installed where namespaces are not allowed. */
    private void selfTest() throws Unavailable, InterruptedException {
        try {
            Process process = processFor(wrap(List.of("/usr/bin/true"), List.of(), 5, 256, false, null))
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
