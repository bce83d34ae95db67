package gfx.tick1.command.shared.grader.cohort;

/**
 * A submission that could not be graded: its folder, why in one line, and whose the cause is. It
 * keeps a row with a blank grade (never "no submission"), and is graded again by the next run.
 */
public record Ungraded(String folder, String why, Cause cause) {

    /** Whose fault it is that a submission was not graded. */
    public enum Cause {
        /** The grader ran short of its own disk or memory: free some, and the same command grades it. */
        GRADER_SHORT,
        /** An error of tick1's (a bug). */
        TICK1_ERROR,
        /** Its result could not be stored in the report's folder (full, read-only, gone). */
        REPORT_FOLDER
    }

    /** Whether the grader is at fault (its resources, or an error of tick1's), not the report's folder. */
    public boolean grader() {
        return cause != Cause.REPORT_FOLDER;
    }
}
