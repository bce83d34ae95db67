package gfx.tick1.command.shared.grader.report;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.model.StudentResult;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A report written again for a cohort without a student it had (withdrawn, or a download put right) keeps no
 * feedback of that student's: the report is of the students graded, and nothing of another stays in it.
 */
class RemovedStudentReportTest {

    private static final String KEPT = "Ann Smith_1001_assignsubmission_file_";
    private static final String REMOVED = "Bob Jones_1003_assignsubmission_file_";

    @TempDir
    Path report;

    @Test
    void aStudentNoLongerInTheCohortHasNoFeedbackFolderAfterTheReportIsWrittenAgain() throws IOException {
        StudentResult kept = SmallCohort.notCompiled(KEPT, "1001", "Ann Smith");
        CohortReport.write(report, List.of(kept, SmallCohort.notCompiled(REMOVED, "1003", "Bob Jones")),
                SmallCohort::grade);
        Files.write(report.resolve("feedback").resolve(REMOVED).resolve("1-tick1-diff.png"), new byte[] {1});

        CohortReport.write(report, List.of(kept), SmallCohort::grade);

        assertThat(report.resolve("feedback").resolve(REMOVED)).as("the removed student's feedback folder")
                .doesNotExist();
        assertThat(report.resolve("feedback").resolve(KEPT).resolve("feedback.txt")).as("the kept student's feedback")
                .isRegularFile();
    }
}
