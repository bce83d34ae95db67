package gfx.tick1.command.shared.grader.intake;

import static gfx.tick1.command.shared.grader.intake.TestZips.entries;
import static gfx.tick1.command.shared.grader.intake.TestZips.zip;
import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.grade.MoodleNaming;
import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every form of name Moodle's "Download all submissions" gives a student's files, made as Moodle's own code makes
 * them ({@link MoodleNaming}, which cites the source), read into the participant Moodle meant: folders of Moodle 4.1
 * and later (no trailing {@code _}) and of earlier versions, blind marking, and files without folders, whose own
 * names can never choose another participant.
 */
class MoodleNamesTest {

    private static final String SPHERE = "package gfx.tick1;\nclass Sphere {}\n";
    private static final String RENDERER = "package gfx.tick1;\nclass Renderer {}\n";

    @TempDir
    Path temp;

    private List<Submission> readZip(Map<String, byte[]> entries) throws IOException {
        return Submissions.read(Files.write(temp.resolve("download.zip"), zip(entries)));
    }

    private List<Submission> inFolder(String folder) throws IOException {
        return readZip(entries(folder + "/Sphere.java", SPHERE, folder + "/Renderer.java", RENDERER));
    }

    @Test
    void aFolderOfMoodle41WithoutTheTrailingUnderscoreIsItsParticipants() throws IOException {
        String folder = MoodleNaming.folder("Ann Lee", 123);

        assertThat(folder).isEqualTo("Ann Lee_123_assignsubmission_file");
        assertThat(inFolder(folder)).singleElement().satisfies(s -> {
            assertThat(s.id()).as("participant id").isEqualTo("123");
            assertThat(s.fullName()).isEqualTo("Ann Lee");
            assertThat(s.problem()).isNull();
            assertThat(Submissions.namedByMoodle(s)).as("named by Moodle").isTrue();
        });
    }

    @Test
    void aFolderOfAnEarlierMoodleWithTheTrailingUnderscoreIsItsParticipants() throws IOException {
        String folder = MoodleNaming.folderBefore41("Ann Lee", 123);

        assertThat(folder).isEqualTo("Ann Lee_123_assignsubmission_file_");
        assertThat(inFolder(folder)).singleElement().satisfies(s -> {
            assertThat(s.id()).isEqualTo("123");
            assertThat(s.fullName()).isEqualTo("Ann Lee");
            assertThat(Submissions.namedByMoodle(s)).isTrue();
        });
    }

    @Test
    void blindMarkingsParticipantFoldersAreEachTheirOwnParticipants() throws IOException {
        List<Submission> cohort = readZip(entries(
                MoodleNaming.folder(MoodleNaming.PARTICIPANT, 7) + "/Sphere.java", SPHERE,
                MoodleNaming.folder(MoodleNaming.PARTICIPANT, 7) + "/Renderer.java", RENDERER,
                MoodleNaming.folder(MoodleNaming.PARTICIPANT, 8) + "/Sphere.java", SPHERE,
                MoodleNaming.folder(MoodleNaming.PARTICIPANT, 8) + "/Renderer.java", RENDERER));

        assertThat(cohort).extracting(Submission::id).containsExactly("7", "8");
        assertThat(cohort).allSatisfy(s -> assertThat(s.problem()).as(s.folder()).isNull());
    }

    @Test
    void underscoresAndQuotesOfAFullNameAreAsMoodleWritesThem() throws IOException {
        String folder = MoodleNaming.folder("Zoë Ann_O'Brien", 42);

        assertThat(folder).as("_ made a space, ' deleted").isEqualTo("Zoë Ann OBrien_42_assignsubmission_file");
        assertThat(inFolder(folder)).singleElement().satisfies(s -> {
            assertThat(s.id()).isEqualTo("42");
            assertThat(s.fullName()).isEqualTo("Zoë Ann OBrien");
        });
    }

    @Test
    void filesWithoutFoldersAreGroupedByTheirParticipantInEveryForm() throws IOException {
        List<Submission> cohort = readZip(entries(
                MoodleNaming.looseFile("Ann Lee", 7, "Sphere.java"), SPHERE,
                MoodleNaming.looseFile("Ann Lee", 7, "Renderer.java"), RENDERER,
                MoodleNaming.looseFile(MoodleNaming.PARTICIPANT, 8, "Sphere.java"), SPHERE,
                MoodleNaming.looseFile(MoodleNaming.PARTICIPANT, 8, "Renderer.java"), RENDERER));

        assertThat(cohort).extracting(Submission::id).containsExactly("7", "8");
        assertThat(cohort).allSatisfy(s -> {
            assertThat(s.problem()).as(s.folder()).isNull();
            assertThat(Submissions.namedByMoodle(s)).as(s.folder()).isTrue();
        });
    }

    @Test
    void aStudentsOwnFileNameCanNeverChooseAnotherParticipant() throws IOException {
        // Participant 66 uploads files named as if they were participant 88's; 88 submitted nothing.
        List<Submission> cohort = readZip(entries(
                MoodleNaming.looseFile("Mallory", 66, "X_88_assignsubmission_file_Sphere.java"), SPHERE,
                MoodleNaming.looseFile("Mallory", 66, "X_88_assignsubmission_file_Renderer.java"), RENDERER));

        assertThat(cohort).as("participant 66's files are 66's alone").singleElement().satisfies(s -> {
            assertThat(s.id()).isEqualTo("66");
            assertThat(s.problem()).as("the files are not named Sphere.java and Renderer.java")
                    .startsWith("no Sphere.java or Renderer.java in the submission; found "
                            + "X_88_assignsubmission_file_Sphere.java and X_88_assignsubmission_file_Renderer.java");
        });
    }

    @Test
    void aStudentsOwnFileNameCannotTakeAnotherParticipantsRowAway() throws IOException {
        // Participant 77 submitted; participant 66 uploads a file named as if it were 77's.
        List<Submission> cohort = readZip(entries(
                MoodleNaming.looseFile("Ann", 77, "Sphere.java"), SPHERE,
                MoodleNaming.looseFile("Ann", 77, "Renderer.java"), RENDERER,
                MoodleNaming.looseFile("Mallory", 66, "X_77_assignsubmission_file_Sphere.java"), SPHERE));

        assertThat(cohort).filteredOn(s -> s.id().equals("77")).singleElement()
                .extracting(Submission::problem).as("77 is graded, not \"two folders\"").isNull();
    }

    @Test
    void otherSubmissionTypesOfEitherFormArePassedOver() throws IOException {
        List<Submission> cohort = readZip(entries(
                "Ann_7_assignsubmission_onlinetext/onlinetext.html", "<p>hi</p>",
                "Ann_7_assignsubmission_onlinetext_/onlinetext.html", "<p>hi</p>",
                "Bob_8_assignsubmission_onlinetext_onlinetext.html", "<p>hi</p>",
                "Cy_9_assignsubmission_file/Sphere.java", SPHERE,
                "Cy_9_assignsubmission_file/Renderer.java", RENDERER));

        assertThat(cohort).as("the one student's folder of files").extracting(Submission::id).containsExactly("9");
    }

    @Test
    void aNameThatFitsNoFormIsNotAParticipants() throws IOException {
        List<Submission> cohort = readZip(entries("ab123/Sphere.java", SPHERE, "ab123/Renderer.java", RENDERER,
                "123/Sphere.java", SPHERE, "123/Renderer.java", RENDERER,
                "Jane_Doe_5_assignsubmission_file_/Sphere.java", SPHERE,
                "Jane_Doe_5_assignsubmission_file_/Renderer.java", RENDERER,
                "Ann_6_assignsubmission_file (1)/Sphere.java", SPHERE,
                "Ann_6_assignsubmission_file (1)/Renderer.java", RENDERER,
                "README.txt", "hello"));

        assertThat(cohort).hasSize(5).allSatisfy(s -> assertThat(Submissions.namedByMoodle(s))
                .as("%s is named by Moodle", s.folder()).isFalse());
    }

    @Test
    void anIdWithALeadingZeroIsNotMoodlesAndTakesNoParticipantsRow() throws IOException {
        // Moodle writes ids as whole numbers; its feedback importer adds 0 to the id it reads, so 066 would be 66's.
        List<Submission> cohort = readZip(entries("X_066_assignsubmission_file/Sphere.java", SPHERE,
                "X_066_assignsubmission_file/Renderer.java", RENDERER,
                "Y_66_assignsubmission_file/Sphere.java", SPHERE,
                "Y_66_assignsubmission_file/Renderer.java", RENDERER));

        assertThat(cohort).as("the two folders").hasSize(2);
        assertThat(cohort.stream().filter(Submissions::namedByMoodle).map(Submission::id))
                .as("the participants named as Moodle names them").containsExactly("66");
    }
}
