package gfx.tick1.command.shared.grader.report;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.model.StudentResult;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Nothing inside the report folder is followed as a link: a link where the report writes a folder is replaced by a
 * folder of its own, so that neither the images of an earlier run are deleted nor feedback written in the folder the
 * link names (as root, that could be any folder of the machine).
 */
class ReportLinksTest {

    @TempDir
    Path temp;
    private Path report;
    private Path elsewhere;
    private List<StudentResult> results;

    @BeforeEach
    void aReportAndAFolderElsewhereHoldingPngs() throws IOException {
        // The images of the small cohort, as the grader stores them, then a fresh report folder.
        Path stored = temp.resolve("stored");
        results = SmallCohort.writeImages(stored);
        report = Files.createDirectories(temp.resolve("report"));
        elsewhere = Files.createDirectories(temp.resolve("elsewhere"));
        Files.writeString(elsewhere.resolve("precious.png"), "not the report's");
    }

    private List<String> elsewhereFiles() throws IOException {
        try (Stream<Path> files = Files.list(elsewhere)) {
            return files.map(path -> path.getFileName().toString()).sorted().toList();
        }
    }

    private String folderOf(int student) {
        return results.get(student).submission().folder();
    }

    @Test
    void aStudentsFeedbackFolderThatIsALinkIsReplacedNotWrittenThrough() throws IOException {
        Path feedback = Files.createDirectories(report.resolve("feedback"));
        Path student = Files.createSymbolicLink(feedback.resolve(folderOf(1)), elsewhere);
        List<Path> images = new ArrayList<>();
        results.forEach(result -> images.add(temp.resolve("stored/feedback").resolve(result.submission().folder())));

        CohortOutputs.placeImages(results, images, report);
        CohortReport.write(report, results, SmallCohort::grade);

        assertThat(elsewhereFiles()).as("the folder the link named").containsExactly("precious.png");
        assertThat(student).as("the student's feedback folder").isDirectory();
        assertThat(Files.isSymbolicLink(student)).as("still a link").isFalse();
        assertThat(student.resolve(FeedbackPage.HTML)).isRegularFile();
    }

    @Test
    void aFeedbackFolderThatIsALinkIsReplacedNotWrittenThrough() throws IOException {
        Files.createDirectories(elsewhere.resolve(folderOf(0)));
        Files.createSymbolicLink(report.resolve("feedback"), elsewhere);

        CohortReport.write(report, results, SmallCohort::grade);

        assertThat(elsewhereFiles()).containsExactly(folderOf(0), "precious.png");
        assertThat(elsewhere.resolve(folderOf(0))).isEmptyDirectory();
        assertThat(Files.isSymbolicLink(report.resolve("feedback"))).isFalse();
        assertThat(report.resolve("feedback").resolve(folderOf(0)).resolve(FeedbackPage.HTML)).isRegularFile();
    }

    @Test
    void theLookAlikePagesFolderThatIsALinkIsReplacedNotWrittenOrEmptiedThrough() throws IOException {
        Files.writeString(elsewhere.resolve(LookalikePage.fileName(7)), "not the report's");
        Files.createSymbolicLink(report.resolve(LookalikePage.FOLDER), elsewhere);

        CohortReport.write(report, results, SmallCohort::grade, List.of());

        assertThat(elsewhereFiles()).as("the folder the link named, whose pair page an earlier run could have left")
                .containsExactly(LookalikePage.fileName(7), "precious.png");
        assertThat(Files.isSymbolicLink(report.resolve(LookalikePage.FOLDER))).as("still a link").isFalse();
    }

    @Test
    void aFileWhereAFeedbackFolderBelongsIsRefusedAndLeftAsItIs() throws IOException {
        Path feedback = Files.createDirectories(report.resolve("feedback"));
        Files.writeString(feedback.resolve(folderOf(0)), "someone's file");

        assertThat(CohortReport.write(report, results, SmallCohort::grade)).as("the students whose feedback is "
                + "not written").singleElement().satisfies(student -> {
                    assertThat(student.folder()).isEqualTo(folderOf(0));
                    assertThat(student.why()).contains("not a folder");
                });
        assertThat(feedback.resolve(folderOf(0))).hasContent("someone's file");
    }

    @Test
    void aLinkWhereTheReportWritesAFileIsReplacedNotWrittenThrough() throws IOException {
        Path target = elsewhere.resolve("precious.png");
        Files.createSymbolicLink(report.resolve(CohortReport.INDEX), target);

        CohortReport.write(report, results, SmallCohort::grade);

        assertThat(target).hasContent("not the report's");
        assertThat(Files.isRegularFile(report.resolve(CohortReport.INDEX), LinkOption.NOFOLLOW_LINKS)).isTrue();
    }
}
