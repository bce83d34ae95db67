package gfx.tick1.command.shared.grader.report;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A student's page of feedback speaks of itself as the place the details are, never of "the feedback". */
class FeedbackPageTest {

    /** A row's reason as grade writes it for grades.csv, where the feedback is somewhere else. */
    private static final StudentResult ROW = new StudentResult(new Submission("s_1_assignsubmission_file_", "1",
            "A Student", null, null, null), new StudentResult.Summary(false, 0, 2,
            new Category.Mistake("N.L not clamped"),
            "tick1.xml: your illuminate gives negative diffuse light when N.L < 0; and 1 more (see the feedback)"),
            List.of(), Duration.ZERO);

    @Test
    void thePageSendsItsReaderToTheScenesBelowNotToTheFeedback() {
        assertThat(FeedbackPage.html(ROW)).as("feedback.html").doesNotContain("see the feedback")
                .contains("and 1 more (see the scenes below)");
    }

    @Test
    void thePlainTextCopySaysTheSame() {
        assertThat(FeedbackPage.text(ROW)).as("feedback.txt").doesNotContain("see the feedback")
                .contains("and 1 more (see the scenes below)");
    }
}
