package gfx.tick1.command.shared.grader.report;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A submission tick1 could not grade is a third outcome, beside passed and failed: the cohort's
 * page counts it apart and shows it as not graded, and its feedback never says it did not pass.
 */
class NotGradedReportTest {

    private static final String FOLDER = "Nell Gray_1009_assignsubmission_file_";

    @TempDir
    Path report;

    @BeforeEach
    void writeTheReport() throws IOException {
        List<StudentResult> results = List.of(SmallCohort.writeImages(report).get(0),
                SmallCohort.notCompiled("Bob Jones_1003_assignsubmission_file_", "1003", "Bob Jones"),
                StudentResult.notGraded(new Submission(FOLDER, "1009", "Nell Gray", null, null, null),
                        "the grader's temporary folder was full"));
        CohortReport.write(report, results, result -> result.graded() ? SmallCohort.grade(result) : "");
    }

    @Test
    void theCohortsPageCountsPassedFailedAndNotGradedApart() throws IOException {
        String page = Files.readString(report.resolve(CohortReport.INDEX), StandardCharsets.UTF_8);

        assertThat(page).as("the summary").contains("<strong id=\"passed-count\">1</strong> of "
                + "<strong id=\"total-count\">3</strong> passed; <strong id=\"failed-count\">1</strong> failed; "
                + "<strong id=\"not-graded-count\">1</strong> not graded.");
    }

    @Test
    void aNotGradedRowIsShownAsNotGradedNeverAsAFail() throws IOException {
        String page = Files.readString(report.resolve(CohortReport.INDEX), StandardCharsets.UTF_8);
        String row = page.substring(page.indexOf("<tr", page.indexOf("Nell Gray") - 300), page.indexOf("Nell Gray"));

        assertThat(page.split("<tr class=\"not-graded\">", -1)).as("rows shown as not graded").hasSize(2);
        assertThat(page).as("the not-graded row's result").contains("<td class=\"result\">not graded</td>");
        assertThat(row).as("the not-graded row").doesNotContain("fail");
    }

    @Test
    void theFeedbackOfANotGradedSubmissionSaysSoAndNeverThatItDidNotPass() throws IOException {
        Path feedback = report.resolve("feedback").resolve(FOLDER);
        String text = Files.readString(feedback.resolve("feedback.txt"), StandardCharsets.UTF_8);
        String html = Files.readString(feedback.resolve("feedback.html"), StandardCharsets.UTF_8);

        assertThat(text).as("feedback.txt").contains("Result: not graded").doesNotContain("not passed");
        assertThat(html).as("feedback.html").contains("<p class=\"verdict not-graded\">Not graded")
                .doesNotContain("not passed", "verdict fail");
    }

    @Test
    void aNotGradedSubmissionIsNoFailureInTheChartOfFailures() throws IOException {
        String page = Files.readString(report.resolve(CohortReport.INDEX), StandardCharsets.UTF_8);

        assertThat(page).as("the chart of failures by diagnosis").doesNotContain("data-label=\"not graded\"");
    }
}
