package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.cli.ExitStatuses;
import gfx.tick1.command.shared.grader.cohort.Ungraded;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** How a cohort's grade ends: the closing line's counts, and the exit status its students not graded give. */
class CohortEndingTest {

    private static Submission submission(String id) {
        return new Submission("S_" + id + "_assignsubmission_file", id, "S", null, null, null);
    }

    private static StudentResult result(String id, boolean passed) {
        return new StudentResult(submission(id), new StudentResult.Summary(passed, passed ? 2 : 1, 2,
                passed ? Category.Outcome.PASSED : new Category.Mistake("wrong"), passed ? "Passed." : "Failed."),
                List.of(), Duration.ZERO);
    }

    @Test
    void theClosingLineCountsPassedFailedAndNotGradedApart() {
        List<StudentResult> results = List.of(result("1", true), result("2", false),
                StudentResult.notGraded(submission("3"), "the grader's temporary folder is full"));

        assertThat(CohortEnding.of(results, 1).line()).isEqualTo("Graded 3 submissions (2 now, 1 from earlier runs): "
                + "1 passed, 1 failed, 1 not graded.");
    }

    @Test
    void studentsNotGradedForTheGradersDiskEndWithAStatusOfTheirOwnNotInternalError() {
        List<Ungraded> ungraded = List.of(new Ungraded("S_3_assignsubmission_file", "the grader's temporary folder "
                + "is full", Ungraded.Cause.GRADER_SHORT));

        assertThat(CohortEnding.status(ungraded, Set.of())).isEqualTo(GradeCommand.EXIT_NOT_GRADED)
                .isNotEqualTo(ExitStatuses.EXIT_INTERNAL);
    }

    @Test
    void studentsNotGradedForAnErrorOfTick1sStillSayInternalError() {
        List<Ungraded> ungraded = List.of(new Ungraded("a", "the grader's memory", Ungraded.Cause.GRADER_SHORT),
                new Ungraded("b", "an error in tick1", Ungraded.Cause.TICK1_ERROR));

        assertThat(CohortEnding.status(ungraded, Set.of())).isEqualTo(ExitStatuses.EXIT_INTERNAL);
    }

    @Test
    void theNotGradedStatusIsInTheHelpAndInCliMdInTheSameWords() throws IOException {
        String words = ExitStatuses.of(GradeCommand.class).get(GradeCommand.EXIT_NOT_GRADED);

        assertThat(words).as("--help's words for the status").contains("not graded").contains("disk");
        assertThat(Files.readString(Path.of("docs/cli.md"))).as("docs/cli.md's tick1 grade statuses")
                .contains("| " + GradeCommand.EXIT_NOT_GRADED + " | " + words + " |");
    }
}
