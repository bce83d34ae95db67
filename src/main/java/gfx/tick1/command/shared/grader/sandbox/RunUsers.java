package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;

/**
 * The users the student's code runs as when the grader is root: one for each job of the grades run
 * at once, and one more for each job's warm compiler, so that none shares a process limit with
 * another nor can signal it. -1 stands for the grader's own user.
 */
final class RunUsers {

    /** The first of the user ids the student's code runs as when the grader is root. */
    static final int FIRST_UID = 1_900_000_000;
    /**
     * Chooses each grader's user, far above the ranges of real users and of containers'
     * subordinate ids: at random, so that two grades at once almost never share one, and so that
     * the id, which the code can read, tells nothing of the machine (a user id made from the
     * grader's process id told a later grade how many processes an earlier one had started).
     */
    private static final SecureRandom RUN_USERS = new SecureRandom();
    /** The distance between the user ids of two jobs: more than the process ids the first one's id is made of. */
    private static final int JOB_UID_STEP = 1_000_000;

    private RunUsers() {
    }

    /** A first user, for job 0 of a grader that is root. */
    static int first() {
        return FIRST_UID + RUN_USERS.nextInt(JOB_UID_STEP);
    }

    /** The user of the {@code job}-th job, from the first job's {@code uid}. */
    static int ofJob(int uid, int job) {
        return uid < 0 ? uid : uid + job * JOB_UID_STEP;
    }

    /** The user of the warm compiler of the job whose user is {@code uid}. */
    static int ofCompiler(int uid) {
        return uid < 0 ? uid : uid + Sandbox.MOST_JOBS * JOB_UID_STEP;
    }

    /**
     * Checks that {@code uid}, the user the student's code runs as, can reach {@code folder} (bubblewrap opens
     * the folders it binds as that user): every folder above it must let others through.
     *
     * @throws IOException saying which folder does not, and what to do
     */
    static void checkReachable(int uid, Path folder) throws IOException {
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

    /** What the run's user may do with a folder shared with it: read it, or own it and so write it. */
    enum Access { READ, OWN }

    /**
     * Makes {@code folder} readable (or, with {@link Access#OWN}, owned) by {@code uid}, the user the
     * student's code runs as, and no one else. Does nothing when that user is the grader (-1).
     */
    static void share(int uid, Path folder, Access access) throws IOException {
        if (uid < 0) {
            return;
        }
        try (var files = Files.walk(folder)) {
            for (Path file : files.toList()) {
                if (access == Access.OWN) {
                    Files.setAttribute(file, "unix:uid", uid);
                }
                Files.setAttribute(file, "unix:gid", uid);
                Files.setAttribute(file, "unix:mode", Files.isDirectory(file) ? 0750 : 0640);
            }
        }
    }
}
