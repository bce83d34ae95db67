package gfx.tick1.command.shared.grader.sandbox;

import java.util.List;
import java.util.Objects;
import java.util.stream.Stream;

/**
 * What a sandbox holds the student's code to, in so far as it can change a grade: code that reads
 * the grader's files, starts many processes or threads, reserves disk space or keeps files it has
 * deleted open can pass under one and fail under another. A result graded under one is therefore
 * not the result under another.
 *
 * @param confined            bubblewrap runs the code; false for {@code --no-sandbox}, and then all below are false
 * @param ownUser             the code runs as a user of its own, held to a number of processes (the grader is root)
 * @param totals              a control group holds each run's memory, processes and CPU in all, not only per process
 * @param reservationsRefused a seccomp filter refuses the calls that reserve disk space a size does not show
 * @param ownDisks            each run's output folder is a tmpfs whose size and number of files the kernel enforces
 */
public record Enforcement(boolean confined, boolean ownUser, boolean totals, boolean reservationsRefused,
        boolean ownDisks) {

    /** The lines that say what this sandbox does not hold the code to, in this order: totals, calls, disk. */
    public List<String> warnings() {
        return Stream.of(totalsNotEnforced(), callsNotRefused(), diskNotEnforced()).filter(Objects::nonNull).toList();
    }

    /**
     * Null when each run is held to totals by a control group of its own; else the one line that
     * says they are not (the limits are then per process only).
     */
    public String totalsNotEnforced() {
        return !confined || totals ? null
                : "no control group can be made here (cgroup v2 not delegated, cgroup v1 memory and pids not "
                        + "writable): the limits are per process; memory, processes and CPU are not limited in all";
    }

    /**
     * Null when the sandbox refuses the calls that reserve disk space a size does not show and those
     * that drop pages from the host's page cache ({@link SeccompFilter}); else the one line that says
     * it does not, on this machine.
     */
    public String callsNotRefused() {
        return !confined || reservationsRefused ? null
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
        return !confined || ownDisks ? null
                : (ownUser ? "no file system can be mounted here" : "grading as a normal user")
                        + ": the output folder of each run is on the host's disk, held to its limit by a count of "
                        + "its files' names, which misses files the code deletes while it holds them open, and the "
                        + "code can load what it writes there as machine code; a cohort's "
                        + "compiler writes its class files there too, counted only once it has compiled";
    }
}
