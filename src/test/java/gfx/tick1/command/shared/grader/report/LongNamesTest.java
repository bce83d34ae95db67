package gfx.tick1.command.shared.grader.report;

import static gfx.tick1.command.shared.grader.report.SmallCohort.notCompiled;
import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.grade.MoodleNaming;
import gfx.tick1.command.shared.grader.model.StudentResult;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Names never stop the report: a folder name longer than a file system takes (255 bytes of UTF-8 for one name on
 * Linux's file systems) is shortened in the report, keeping {@code _<id>_} and Moodle's plugin part so that
 * Moodle's feedback importer still finds the student ({@link MoodleNaming#importerParticipant}); a student whose
 * feedback cannot be written is that student's failure alone.
 */
class LongNamesTest {

    /** The most bytes of one name in a folder of ext4, XFS, Btrfs and tmpfs. */
    private static final int NAME_MAX = 255;

    @TempDir
    Path report;

    private static int bytes(String name) {
        return name.getBytes(StandardCharsets.UTF_8).length;
    }

    @Test
    void aHundredLetterCjkNameIsShortenedKeepingTheIdAndThePluginPart() throws IOException {
        String name = "陈".repeat(100);
        String folder = MoodleNaming.folder(name, 4242);
        assertThat(bytes(folder)).as("the download's folder, in bytes").isGreaterThan(NAME_MAX);
        List<StudentResult> results = CohortOutputs.forReport(List.of(notCompiled(folder, "4242", name),
                notCompiled(MoodleNaming.folder("Ann Lee", 7), "7", "Ann Lee")));

        List<Unwritten> unwritten = CohortOutputs.placeImages(results, List.of(report, report), report);
        CohortReport.write(report, results, SmallCohort::grade);

        String shortened = results.get(0).submission().folder();
        assertThat(unwritten).as("students whose feedback could not be written").isEmpty();
        assertThat(bytes(shortened)).as("bytes of the report's folder").isLessThanOrEqualTo(NAME_MAX);
        assertThat(shortened).as("the report's folder").startsWith("陈陈").endsWith("_4242_assignsubmission_file");
        assertThat(report.resolve("feedback").resolve(shortened).resolve(FeedbackPage.HTML)).isRegularFile();
        assertThat(SmallCohort.zipEntries(report)).filteredOn(entry -> MoodleNaming.importerParticipant(entry) == 4242)
                .as("feedback.zip's files that Moodle gives participant 4242").hasSize(2);
    }

    @Test
    void aLongNameOfEveryFormIsShortenedToFitAndStaysDifferentFromTheOthers() {
        String cjk = "陈".repeat(100);
        List<StudentResult> results = CohortOutputs.forReport(List.of(
                notCompiled(MoodleNaming.folderBefore41(cjk, 1), "1", cjk),
                notCompiled(MoodleNaming.folder(cjk, 2), "2", cjk),
                notCompiled(MoodleNaming.prefix(cjk, 3) + "_assignsubmission_file_", "3", cjk),
                notCompiled("x".repeat(300), "x".repeat(300), "x".repeat(300)),
                notCompiled("x".repeat(301), "x".repeat(301), "x".repeat(301))));

        List<String> folders = results.stream().map(result -> result.submission().folder()).toList();
        assertThat(folders).as("the report's folders").doesNotHaveDuplicates()
                .allSatisfy(folder -> assertThat(bytes(folder)).as(folder).isLessThanOrEqualTo(NAME_MAX));
        assertThat(folders.subList(0, 3)).as("Moodle's folders, by Moodle's importer")
                .extracting(MoodleNaming::importerParticipant).containsExactly(1L, 2L, 3L);
        assertThat(folders.get(0)).endsWith("_1_assignsubmission_file_");
    }

    @Test
    void aStudentWhoseFeedbackCannotBeWrittenFailsAloneWithTheReason() throws IOException {
        List<StudentResult> results = CohortOutputs.forReport(List.of(
                notCompiled("Ann_7_assignsubmission_file", "7", "Ann"),
                notCompiled("Bob_8_assignsubmission_file", "8", "Bob")));
        // Something that is not a folder where Ann's feedback folder belongs.
        Files.writeString(Files.createDirectories(report.resolve("feedback")).resolve("Ann_7_assignsubmission_file"),
                "a file");

        List<Unwritten> images = CohortOutputs.placeImages(results, List.of(report, report), report);
        List<Unwritten> pages = CohortReport.write(report, results, SmallCohort::grade);

        for (List<Unwritten> unwritten : List.of(images, pages)) {
            assertThat(unwritten).as("why Ann's feedback is not written").singleElement().satisfies(ann -> {
                assertThat(ann.folder()).isEqualTo("Ann_7_assignsubmission_file");
                assertThat(ann.why()).contains("not a folder");
            });
        }
        assertThat(report.resolve("feedback/Bob_8_assignsubmission_file").resolve(FeedbackPage.HTML)).isRegularFile();
        assertThat(report.resolve(CohortReport.INDEX)).isRegularFile();
        assertThat(SmallCohort.zipEntries(report)).as("feedback.zip").isNotEmpty()
                .allSatisfy(entry -> assertThat(entry).startsWith("Bob_8_assignsubmission_file/"));
    }
}
