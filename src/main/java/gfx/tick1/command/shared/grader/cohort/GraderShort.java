package gfx.tick1.command.shared.grader.cohort;

import java.io.IOException;

/**
 * A grade that the grader's own disk may have failed ({@link GraderDisk}): the submission is "not
 * graded", for a reason of the grader's, not a bug of tick1's, and the same command grades it again
 * once there is room.
 */
final class GraderShort extends IOException {

    private static final long serialVersionUID = 1L;

    /** {@code why}: the grader's disk, in words for the course staff. */
    GraderShort(String why) {
        super(why);
    }
}
