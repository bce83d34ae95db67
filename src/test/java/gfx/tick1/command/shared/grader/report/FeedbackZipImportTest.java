package gfx.tick1.command.shared.grader.report;

import static gfx.tick1.command.shared.grader.report.SmallCohort.notCompiled;
import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.grade.MoodleNaming;
import gfx.tick1.command.shared.grader.model.StudentResult;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * feedback.zip as Moodle's "Upload multiple feedback files in a zip" reads it ({@link
 * MoodleNaming#importerParticipant}, from mod/assign/feedback/file/importziplib.php): every file of every student
 * goes to that student, whichever form of Moodle's names their folder had in the download.
 */
class FeedbackZipImportTest {

    @TempDir
    Path report;

    @Test
    void everyFormOfMoodlesNamesGoesBackToItsParticipant() throws IOException {
        List<StudentResult> results = List.of(
                notCompiled(MoodleNaming.folder("Ann Lee", 101), "101", "Ann Lee"),
                notCompiled(MoodleNaming.folderBefore41("Bob Ray", 102), "102", "Bob Ray"),
                notCompiled(MoodleNaming.folder(MoodleNaming.PARTICIPANT, 103), "103", MoodleNaming.PARTICIPANT),
                // A download without folders: the student's folder is the prefix of their files' names.
                notCompiled(MoodleNaming.prefix("Cy Dee", 104) + "_assignsubmission_file_", "104", "Cy Dee"),
                notCompiled(MoodleNaming.folder("Zoë 陈伟 O_Brien", 105), "105", "Zoë 陈伟 O Brien"));

        CohortReport.write(report, CohortOutputs.forReport(results), SmallCohort::grade);

        List<String> entries = SmallCohort.zipEntries(report);
        for (StudentResult result : results) {
            long id = Long.parseLong(result.submission().id());
            assertThat(entries).as("entries for participant %d", id)
                    .filteredOn(entry -> MoodleNaming.importerParticipant(entry) == id)
                    .hasSize(2);
        }
        assertThat(entries).as("every entry is some participant's")
                .allSatisfy(entry -> assertThat(MoodleNaming.importerParticipant(entry)).as(entry).isPositive());
    }
}
