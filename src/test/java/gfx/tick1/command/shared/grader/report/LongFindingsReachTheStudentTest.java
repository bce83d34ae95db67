package gfx.tick1.command.shared.grader.report;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.LongFindings;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The report's bounds hold against a student's text, never against tick1's own findings: the
 * worksheet's comment, feedback.html and feedback.txt give every finding whole and every "reread"
 * line, and where a bound must cut, it cuts after a whole finding and says where the rest is.
 */
class LongFindingsReachTheStudentTest {

    private static final List<String> EXPLANATION = List.of("98343 pixels differ", "behaviour: "
            + LongFindings.INTERSECTION, "behaviour: " + LongFindings.ILLUMINATE, LongFindings.REREAD);

    private static StudentResult result(String reason, List<String> explanation) {
        return new StudentResult(new Submission("s_1_assignsubmission_file_", "1", "A Student", null, null, null),
                new StudentResult.Summary(false, 0, 1, new Category.Mistake("differs from ours"), reason),
                List.of(new SceneResult("tick1.xml", false, false, explanation, SceneResult.Images.NONE)),
                Duration.ZERO);
    }

    private static final StudentResult REPORTED = CohortOutputs.forReport(List.of(result(LongFindings.REASON,
            EXPLANATION))).get(0);

    @Test
    void theWorksheetsCommentHoldsEveryFindingWhole() {
        assertThat(CellText.comment(REPORTED.reason())).as("grades.csv's comment").isEqualTo(LongFindings.REASON);
    }

    @Test
    void aCommentOverTheCellsLimitEndsAfterAWholeFindingAndSaysWhereTheRestIs() {
        String many = LongFindings.HEAD + (" " + LongFindings.sentence(LongFindings.ILLUMINATE)).repeat(8);

        assertThat(CellText.comment(CohortOutputs.forReport(List.of(result(many, EXPLANATION))).get(0).reason()))
                .as("grades.csv's comment").startsWith(LongFindings.HEAD)
                .endsWith(LongFindings.sentence(LongFindings.ILLUMINATE) + " (more in feedback.html)")
                .hasSizeLessThanOrEqualTo(CellText.MAX_CELL);
    }

    @Test
    void feedbackHtmlGivesEveryFindingWholeAndTheRereadLine() {
        assertThat(FeedbackPage.html(REPORTED)).as("feedback.html").contains(Html.escape("behaviour: "
                + LongFindings.INTERSECTION), Html.escape("behaviour: " + LongFindings.ILLUMINATE),
                Html.escape(LongFindings.REREAD), Html.escape(LongFindings.sentence(LongFindings.ILLUMINATE)));
    }

    @Test
    void feedbackTxtGivesEveryFindingWholeAndTheRereadLine() {
        assertThat(FeedbackPage.text(REPORTED)).as("feedback.txt").contains("behaviour: " + LongFindings.INTERSECTION,
                "behaviour: " + LongFindings.ILLUMINATE, LongFindings.REREAD,
                LongFindings.sentence(LongFindings.ILLUMINATE));
    }

    @Test
    void anExplanationOverItsLimitOfLinesKeepsItsRereadLine() {
        List<String> lines = new ArrayList<>(Collections.nCopies(CohortOutputs.MAX_LINES + 5,
                "a line a student printed"));
        lines.add(LongFindings.REREAD);

        List<String> kept = CohortOutputs.forReport(List.of(result("FAILED.", lines))).get(0).scenes().get(0)
                .explanation();

        assertThat(kept).as("the explanation the report keeps").endsWith(LongFindings.REREAD)
                .hasSizeLessThanOrEqualTo(CohortOutputs.MAX_LINES + 1).contains("(and 6 more lines)");
    }
}
