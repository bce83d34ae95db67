package gfx.tick1.command.shared.grader.cohort;

import java.io.IOException;

/**
 * A result that the report's folder did not take (full, read-only, gone): the submission is "not graded" for a
 * reason of the report folder's, not a bug of tick1's, and the same command grades it once the folder takes files.
 */
final class ReportUnwritable extends IOException {

    private static final long serialVersionUID = 1L;

    /** {@code why}: the file system's reason, in its own words. */
    ReportUnwritable(String why) {
        super(why);
    }
}
