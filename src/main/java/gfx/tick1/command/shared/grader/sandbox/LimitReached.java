package gfx.tick1.command.shared.grader.sandbox;

/**
 * A total a run reached (memory, processes and threads, or its output folder): which, and the
 * words that tell the student. Memory and the output folder's limit stop the whole run; the
 * process total is reached while the run goes on.
 */
public record LimitReached(NoImage kind, String words) {

    /** Whether the run was stopped by it, so nothing of the run counts. */
    boolean stoppedTheRun() {
        return kind != NoImage.PROCESS_LIMIT;
    }
}
