package gfx.tick1.command.shared.grader.sandbox;

import gfx.tick1.engine.io.OnExit;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.ReentrantLock;

/**
 * What this machine gives every sandbox made here: the bwrap (null for none), where control
 * groups are made (or null), the seccomp filter's file (or null), and whether each run's output
 * folder can be a file system of its own, the host's files the runs see (null for none), and
 * the stricter filter's file of the runs that render hidden scenes (null with no filter).
 */
record Host(Path bwrap, Cgroup.Place cgroups, Path seccompFilter, boolean ownDisks, SystemFiles system,
        Path hiddenRunFilter) {

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
    /** "host" keeps each run's output folder on the host's disk, as where no tmpfs can be mounted (for the tests). */
    private static final String OUTPUT_DISKS_PROPERTY = "tick1.grade.outputDisks";

    /** No sandbox: {@link Sandbox#unconfined()}. */
    static final Host NONE = new Host(null, null, null, false, null, null);

    /**
     * What this machine gives a sandbox run by {@code bwrap}, an executable, for a grader that is
     * root or not.
     *
     * @throws Sandbox.Unavailable when the filter cannot be written or the host's files cannot be listed
     */
    static Host find(Path bwrap, boolean root) throws Sandbox.Unavailable, InterruptedException {
        Path seccompFilter;
        Path hiddenRunFilter;
        try {
            SeccompFilter.Processes processes = Boolean.getBoolean(PROCESSES_PROPERTY)
                    ? SeccompFilter.Processes.ALLOWED : SeccompFilter.Processes.REFUSED;
            seccompFilter = SeccompFilter.writeForThisMachine(SceneBatch.PUBLIC, processes);
            hiddenRunFilter = SeccompFilter.writeForThisMachine(SceneBatch.HIDDEN, processes);
        } catch (IOException e) {
            throw new Sandbox.Unavailable("cannot write the sandbox's seccomp filter (" + e.getMessage() + ")");
        }
        SystemFiles system;
        try {
            system = SystemFiles.of(Sandbox.javaHome(), java.util.Arrays.stream(
                    System.getProperty(ALSO_SHOWN_PROPERTY, "").split(java.io.File.pathSeparator))
                    .filter(name -> !name.isEmpty()).map(Path::of).toList());
        } catch (IOException e) {
            throw new Sandbox.Unavailable("cannot list the files of the JDK and the libraries java loads ("
                    + e.getMessage() + ")");
        }
        return new Host(bwrap, Cgroup.find(), seccompFilter, root
                && !"host".equals(System.getProperty(OUTPUT_DISKS_PROPERTY)) && canMountOutputDisks(), system,
                hiddenRunFilter);
    }

    /**
     * Whether this grader can mount each run a tmpfs of its own: it mounts one, in a new temporary folder. The
     * folder goes however tick1 ends: a diff makes its sandbox while it parses, and may end before the trial does.
     * The JVM's end waits for the mount and unmount under way, then deletes the folder; after it, no trial begins.
     */
    static boolean canMountOutputDisks() {
        ReentrantLock trying = new ReentrantLock();
        AtomicReference<Path> scratch = new AtomicReference<>();
        try {
            OnExit cleanUp = OnExit.run("tick1-trial-mount", () -> {
                trying.lock();
                try {
                    if (scratch.get() != null) {
                        WorkFolder.delete(scratch.get());
                    }
                } finally {
                    trying.unlock();
                }
            });
            trying.lock();
            try {
                if (OnExit.stopping()) {   // the hook may have run already: no trial now
                    return false;
                }
                scratch.set(Leftovers.newWorkFolder("mount"));
                return OutputDisk.canMount(scratch.get());
            } finally {
                trying.unlock();
                cleanUp.now();
            }
        } catch (IOException e) {
            return false;
        }
    }
}
