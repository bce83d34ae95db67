package gfx.tick1.command.grade;

import gfx.tick1.command.shared.cli.ExitStatuses;
import gfx.tick1.command.shared.grader.cohort.Ungraded;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.engine.io.Counted;
import java.util.List;
import java.util.Set;

/**
 * How a cohort's grade ends: the closing line that counts its results, and the exit status that
 * the submissions it could not grade give.
 *
 * @param total    every result of the report
 * @param stored   those from earlier runs
 * @param problems those never run: a problem with their files (a missing file, ...), neither now nor earlier
 * @param passed   those that passed
 * @param notGraded those tick1 could not grade (its disk, its memory, an error of its own): no verdict, so
 *                 counted neither as passed nor as failed
 */
record CohortEnding(long total, long stored, long problems, long passed, long notGraded) {

    /** The ending of a report of {@code results}, {@code stored} of them from earlier runs. */
    static CohortEnding of(List<StudentResult> results, int stored) {
        return new CohortEnding(results.size(), stored,
                results.stream().filter(result -> result.submission().problem() != null).count(),
                results.stream().filter(StudentResult::passed).count(),
                results.stream().filter(result -> !result.graded()).count());
    }

    /** "Graded 3 submissions (2 now, 1 from earlier runs): 1 passed, 1 failed, 1 not graded." */
    String line() {
        return "Graded " + Counted.of((int) total, "submission") + " (" + (total - stored - problems) + " now, "
                + stored + " from earlier runs" + (problems > 0 ? ", " + problems + " not run: a problem with their "
                + "files" : "") + "): " + passed + " passed, " + (total - passed - notGraded) + " failed, " + notGraded
                + " not graded.";
    }

    /**
     * The exit status of a report written whole but for {@code ungraded} and the feedback of the students
     * {@code unwritten}: an error of tick1's first (it asks for a report), then the grader's own shortage (it
     * asks for room and the same command again), then the report's folder.
     */
    static int status(List<Ungraded> ungraded, Set<String> unwritten) {
        if (ungraded.stream().anyMatch(one -> one.cause() == Ungraded.Cause.TICK1_ERROR)) {
            return ExitStatuses.EXIT_INTERNAL;
        }
        if (ungraded.stream().anyMatch(one -> one.cause() == Ungraded.Cause.GRADER_SHORT)) {
            return GradeCommand.EXIT_NOT_GRADED;
        }
        return ungraded.isEmpty() && unwritten.isEmpty() ? GradeCommand.EXIT_PASS : GradeCommand.EXIT_CANNOT_WRITE;
    }
}
