package gfx.tick1.command.shared.grader.sandbox;

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
}
