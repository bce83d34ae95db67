package gfx.tick1.grade.report;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.grade.MoodleNaming;
import gfx.tick1.grade.model.StudentResult;
import gfx.tick1.grade.model.Submission;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
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

    private static StudentResult failed(String folder, long id, String name) {
        return new StudentResult(new Submission(folder, String.valueOf(id), name, null, null, null), false, 0, 0,
                "does not compile", "The code does not compile.", List.of(), Duration.ofMillis(10));
    }

    private List<String> zipEntries() throws IOException {
        List<String> names = new ArrayList<>();
        try (InputStream file = Files.newInputStream(report.resolve("feedback.zip"));
                ZipInputStream zip = new ZipInputStream(file)) {
            for (ZipEntry entry = zip.getNextEntry(); entry != null; entry = zip.getNextEntry()) {
                names.add(entry.getName());
            }
        }
        return names;
    }

    @Test
    void everyFormOfMoodlesNamesGoesBackToItsParticipant() throws IOException {
        List<StudentResult> results = List.of(
                failed(MoodleNaming.folder("Ann Lee", 101), 101, "Ann Lee"),
                failed(MoodleNaming.folderBefore41("Bob Ray", 102), 102, "Bob Ray"),
                failed(MoodleNaming.folder(MoodleNaming.PARTICIPANT, 103), 103, MoodleNaming.PARTICIPANT),
                // A download without folders: the student's folder is the prefix of their files' names.
                failed(MoodleNaming.prefix("Cy Dee", 104) + "_assignsubmission_file_", 104, "Cy Dee"),
                failed(MoodleNaming.folder("Zoë 陈伟 O_Brien", 105), 105, "Zoë 陈伟 O Brien"));

        CohortReport.write(report, CohortOutputs.forReport(results), SmallCohort::grade);

        List<String> entries = zipEntries();
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
