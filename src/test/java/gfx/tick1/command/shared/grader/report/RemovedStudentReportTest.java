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

    @Test
    void aFileTick1NeverWritesInARemovedStudentsFolderIsKeptWithTheFolder() throws IOException {
        StudentResult kept = SmallCohort.notCompiled(KEPT, "1001", "Ann Smith");
        CohortReport.write(report, List.of(kept, SmallCohort.notCompiled(REMOVED, "1003", "Bob Jones")),
                SmallCohort::grade);
        Path comments = Files.writeString(report.resolve("feedback").resolve(REMOVED).resolve("marker-comments.txt"),
                "a marker's own words");

        CohortReport.write(report, List.of(kept), SmallCohort::grade);

        assertThat(comments).as("a marker's file in the removed student's feedback folder").hasContent(
                "a marker's own words");
        assertThat(report.resolve("feedback").resolve(REMOVED).resolve("feedback.txt"))
                .as("tick1's feedback in the removed student's folder").doesNotExist();
    }

    @Test
    void aFolderOfTheUsersOwnInTheFeedbackFolderKeepsItsFilesOnAFirstGrade() throws IOException {
        Path notes = Files.createDirectories(report.resolve("feedback").resolve("My notes")).resolve("notes.txt");
        Files.writeString(notes, "the user's notes");

        CohortReport.write(report, List.of(SmallCohort.notCompiled(KEPT, "1001", "Ann Smith")), SmallCohort::grade);

        assertThat(notes).as("the user's notes in a folder of the feedback folder").hasContent("the user's notes");
    }
}
