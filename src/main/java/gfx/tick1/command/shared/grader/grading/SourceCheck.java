package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.intake.StudentFile;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.Submission;

/**
 * The grade's first step: the submission has its two files, each is UTF-8, and each declares the
 * package the starter code's classes are in. Nothing of the student's code runs here.
 */
final class SourceCheck {

    /** What checking found: the two files as text, or why the submission cannot be compiled. */
    sealed interface Checked {
    }

    /** The student's two files as text. */
    record Sources(String sphere, String renderer) implements Checked {
    }

    /** Why the submission cannot be compiled, and its category for the cohort's chart. */
    record Problem(Category category, String reason) implements Checked {
    }

    private SourceCheck() {
    }

    static Checked check(Submission submission) {
        if (submission.problem() != null) {
            return new Problem(Category.Outcome.SUBMISSION_PROBLEM, submission.problem());
        }
        Sources code;
        try {
            code = new Sources(StudentFile.decode(submission.sphere().path(), submission.sphere().content()),
                    StudentFile.decode(submission.renderer().path(), submission.renderer().content()));
        } catch (StudentFile.NotUtf8Exception e) {
            return new Problem(Category.Outcome.NOT_UTF8, e.getMessage());
        }
        return StudentFile.packageProblem(submission.sphere().path(), code.sphere())
                .or(() -> StudentFile.packageProblem(submission.renderer().path(), code.renderer()))
                .<Checked>map(problem -> new Problem(Category.Outcome.WRONG_PACKAGE, problem))
                .orElse(code);
    }
}
