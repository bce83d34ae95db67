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
 *       read-only, the folders {@code grade} binds in
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

    /** Debian's bwrap; the system property tick1.grade.bwrap names another (the tests name a missing one). */
    private static final String BWRAP_PROPERTY = "tick1.grade.bwrap";
    private static final Path TRUE = Path.of("/usr/bin/true");

    /** A folder of the grader's, bound into the sandbox at {@code inside}, writable or not. */
    record Bind(Path outside, String inside, boolean writable) {
    }

    /** How many grades one program may run at once, each under a user of its own: see {@link #forJob}. */
    public static final int MOST_JOBS = 64;

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
     * The same sandbox, after checking that it hides {@code paths} (the organiser's scenes and
     * their folder) from the runs, as it hides every file of the host's but the JDK and the
     * libraries it loads: the runs get their scenes only through the folder bound for them.
     *
     * @throws CannotHide when one is, holds or lies in what the runs see (the JDK, a library)
     */
    public Sandbox hiding(List<Path> paths) throws CannotHide {
        Secrets.refuseWhatTheRunsSee(paths, host.system(), Secrets.realPath(javaHome()) == null ? javaHome()
                : Secrets.realPath(javaHome()));
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
        return new Sandbox(host, RunUsers.ofJob(uid, job), job);
    }

    /**
     * The sandbox of this job's warm compiler: the same core, and a user of its own, so that the
     * compiler (which lives from one submission to the next) and the student's code never share a
     * process limit nor can signal each other. Only for a sandbox {@link #forJob} made.
     */
    public Sandbox forCompiler() {
        return new Sandbox(host, RunUsers.ofCompiler(uid), job);
    }

    /** No sandbox at all: the student's code runs as the grader, with the grader's files and network. */
    public static Sandbox unconfined() {
        return new Sandbox(Host.NONE, -1, 0);
    }

    /**
     * The bubblewrap sandbox, after checking that it can be made here.
     *
     * @throws Unavailable when bubblewrap is missing or cannot create namespaces
     */
    public static Sandbox confined() throws Unavailable, InterruptedException {
        Path bwrap = Path.of(System.getProperty(BWRAP_PROPERTY, "/usr/bin/bwrap"));
        if (!System.getProperty("os.name", "").startsWith("Linux")) {
            // bubblewrap is Linux's alone: there is nothing to install.
            throw new Unavailable("the sandbox needs Linux (this is " + System.getProperty("os.name") + ")");
        }
        if (!Files.isExecutable(bwrap)) {
            throw new Unavailable("bubblewrap is not installed", "install the " + PACKAGE + " package (apt-get install "
                    + PACKAGE + ")");
        }
        if (!Files.isExecutable(RunLimits.PRLIMIT)) {
            throw new Unavailable("prlimit is not installed", "install the util-linux package (apt-get install "
                    + "util-linux)");
        }
        int uid = ThisUser.uid();
        if (uid < 0) {
            throw new Unavailable("cannot tell which user this is (/proc/self has no owner to read)");
        }
        boolean root = uid == 0 && Files.isExecutable(RunLimits.SETPRIV);
        Host host = Host.find(bwrap, root);
        Sandbox sandbox = new Sandbox(host, root ? RunUsers.first() : -1, 0);
        sandbox.selfTest();
        return sandbox;
    }

    /** Why the sandbox cannot be made, and what would make it, where that is known. */
    public static final class Unavailable extends Exception {
        private static final long serialVersionUID = 1L;

        /** What the kernel's refusal of namespaces calls for: installing bubblewrap again would change nothing. */
        static final String ALLOW_NAMESPACES = "the kernel refuses new user namespaces here, as in a container or a "
                + "chroot: grade where they are allowed (sysctl kernel.unprivileged_userns_clone=1 where that "
                + "setting exists, and user.max_user_namespaces above 0)";

        private final String remedy;

        Unavailable(String reason) {
            this(reason, null);
        }

        Unavailable(String reason, String remedy) {
            super(reason);
            this.remedy = remedy;
        }

        /** What to do so that the sandbox can be made (install a package, allow namespaces), or null if not known. */
        public String remedy() {
            return remedy;
        }
    }

    boolean isConfined() {
        return confined;
    }

    /** The user the student's code runs as; -1 for the grader's own. */
    int runUser() {
        return uid;
    }

    /**
     * Checks that the user the student's code runs as can reach {@code folder} ({@link RunUsers#checkReachable}).
     *
     * @throws IOException saying which folder does not, and what to do
     */
    public void checkReachable(Path folder) throws IOException {
        RunUsers.checkReachable(uid, folder);
    }

    /** Makes {@code folder} readable by the run's user alone ({@link RunUsers#share}). */
    public void share(Path folder) throws IOException {
        RunUsers.share(uid, folder, RunUsers.Access.READ);
    }

    /** Makes {@code folder} owned, so writable, by the run's user alone ({@link RunUsers#share}). */
    public void shareWritable(Path folder) throws IOException {
        RunUsers.share(uid, folder, RunUsers.Access.OWN);
    }

    /** What this sandbox holds the code to: results graded under other rules are graded again. */
    public Enforcement enforcement() {
        return new Enforcement(confined, uid >= 0, confined && host.cgroups() != null,
                confined && host.seccompFilter() != null, confined && host.ownDisks());
    }

    /**
     * The file system of one run's output folder {@code folder}, an empty folder this sandbox has
     * {@link #shareWritable shared} for writing: a tmpfs of its own where the sandbox can mount one (close
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

    /** A control group for one run held to {@code totals}, or null when none can be made. */
    Cgroup cgroupFor(Cgroup.Totals totals) throws IOException {
        return confined && host.cgroups() != null ? Cgroup.create(host.cgroups(), totals) : null;
    }

    /**
     * The command that runs {@code command} inside the sandbox, with {@code binds}, held to
     * {@code limits} and, where there is one, to {@code cgroup}'s totals; for a hidden {@code batch},
     * under the hidden runs' stricter seccomp filter.
     */
    List<String> wrap(List<String> command, List<Bind> binds, RunLimits limits, Cgroup cgroup, SceneBatch batch) {
        if (!confined) {
            return command;
        }
        List<String> wrapped = new ArrayList<>(RunLimits.startCommand(cgroup,
                batch == SceneBatch.HIDDEN ? host.hiddenRunFilter() : host.seccompFilter()));
        wrapped.addAll(limits.programs(uid, job));
        wrapped.addAll(List.of("--", host.bwrap().toString(),
                "--unshare-all", "--unshare-user", "--disable-userns",
                "--die-with-parent", "--new-session", "--cap-drop", "ALL",
                "--clearenv", "--setenv", "PATH", "/usr/bin", "--setenv", "LANG", "C.UTF-8",
                "--setenv", "MALLOC_ARENA_MAX", "2"));
        if (host.seccompFilter() != null) {
            wrapped.addAll(List.of("--seccomp", Integer.toString(RunLimits.FILTER_FD)));
        }
        wrapped.addAll(Mounts.arguments(host.system(), binds));
        wrapped.addAll(command);
        return wrapped;
    }

    /** The JDK this program runs on, whose java the runs start. */
    static Path javaHome() {
        return Path.of(System.getProperty("java.home")).toAbsolutePath();
    }

    /** Why the sandbox cannot hide the organiser's scenes: in one line for the organiser. */
    public static final class CannotHide extends IOException {
        private static final long serialVersionUID = 1L;

        CannotHide(String reason) {
            super(reason);
        }
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
     * Runs {@code true} in the sandbox, bound in for this run alone (it loads only libraries java
     * loads too): bubblewrap may be installed where namespaces are not allowed.
     */
    private void selfTest() throws Unavailable, InterruptedException {
        try {
            Process process = processFor(wrap(List.of(TRUE.toString()), List.of(new Bind(TRUE, TRUE.toString(),
                    false)), new RunLimits(5, 256, false), null, SceneBatch.PUBLIC)).redirectErrorStream(true).start();
            process.getOutputStream().close();
            byte[] said = process.getInputStream().readNBytes(4096);
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                throw new Unavailable("bubblewrap did not start");
            }
            if (process.exitValue() != 0) {
                String why = ChildOutput.printable(new String(said, java.nio.charset.StandardCharsets.UTF_8)).strip();
                String first = why.lines().findFirst().orElse("");
                throw new Unavailable("bubblewrap cannot create a sandbox here" + (why.isEmpty() ? "" : " (" + first
                        + ")"), first.toLowerCase(java.util.Locale.ROOT).contains("namespace")
                                ? Unavailable.ALLOW_NAMESPACES : null);
            }
        } catch (IOException e) {
            throw new Unavailable("bubblewrap cannot be started: " + e.getMessage());
        }
    }
}
