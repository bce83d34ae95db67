package gfx.tick1.command.shared.grader.intake;

import gfx.tick1.command.shared.grader.model.CohortInputException;
import gfx.tick1.command.shared.grader.model.Submission;
import static gfx.tick1.command.shared.grader.intake.TestZips.entries;
import static gfx.tick1.command.shared.grader.intake.TestZips.zip;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SubmissionsTest {

    private static final String SPHERE = "package gfx.tick1;\nclass Sphere {}\n";
    private static final String RENDERER = "package gfx.tick1;\nclass Renderer {}\n";
    private static final IntakeLimits SMALL = new IntakeLimits(1024, 64 * 1024, 128 * 1024, 20, 256 * 1024);

    @TempDir
    Path temp;

    private Path write(String name, byte[] bytes) throws IOException {
        return Files.write(temp.resolve(name), bytes);
    }

    private List<Submission> readZip(Map<String, byte[]> entries) throws IOException {
        return Submissions.read(write("cohort.zip", zip(entries)));
    }

    /** A download of one folder holding both files. */
    private List<Submission> bothFilesIn(String folder) throws IOException {
        return readZip(entries(folder + "/Sphere.java", SPHERE, folder + "/Renderer.java", RENDERER));
    }

    private static String text(Submission.SourceFile file) {
        return new String(file.content(), StandardCharsets.UTF_8);
    }

    @Test
    void moodleFolderNamesGiveTheParticipantIdAndFullName() throws IOException {
        String folder = "Zoë Ann OBrien_42_assignsubmission_file_";
        List<Submission> cohort = bothFilesIn(folder);

        assertThat(cohort).singleElement().satisfies(s -> {
            assertThat(s.folder()).isEqualTo(folder);
            assertThat(s.id()).isEqualTo("42");
            assertThat(s.fullName()).isEqualTo("Zoë Ann OBrien");
            assertThat(s.problem()).isNull();
            assertThat(text(s.sphere())).isEqualTo(SPHERE);
            assertThat(text(s.renderer())).isEqualTo(RENDERER);
            assertThat(s.sphere().path()).isEqualTo("Sphere.java");
        });
    }

    @Test
    void aFolderWhoseNameHoldsAnUnderscoreBeforeTheIdIsNotMoodlesAndKeepsItsWholeName() throws IOException {
        // Moodle makes every _ of a full name a space: this folder was named by hand.
        String folder = "Zoë Ann_O'Brien_42_assignsubmission_file_";

        assertThat(bothFilesIn(folder)).singleElement().satisfies(s -> {
            assertThat(s.id()).as("no participant id").isEqualTo(folder);
            assertThat(Submissions.namedByMoodle(s)).as("named by Moodle").isFalse();
        });
    }

    @Test
    void anyOtherFolderNameIsBothTheIdAndTheName() throws IOException {
        List<Submission> cohort = readZip(entries("ab123/Sphere.java", SPHERE, "ab123/Renderer.java", RENDERER));

        assertThat(cohort).singleElement().satisfies(s -> {
            assertThat(s.id()).isEqualTo("ab123");
            assertThat(s.fullName()).isEqualTo("ab123");
        });
    }

    @Test
    void theFilesMayLieAnywhereInTheStudentsFolder() throws IOException {
        List<Submission> cohort = readZip(entries("s/project/src/gfx/tick1/Sphere.java", SPHERE,
                "s/Renderer.java", RENDERER, "s/notes.txt", "hello"));

        assertThat(cohort.get(0).sphere().path()).isEqualTo("project/src/gfx/tick1/Sphere.java");
        assertThat(cohort.get(0).renderer().path()).isEqualTo("Renderer.java");
    }

    @Test
    void theFilesMayLieInsideOneZipInTheStudentsFolder() throws IOException {
        byte[] work = zip(entries("src/Sphere.java", SPHERE, "src/Renderer.java", RENDERER));
        List<Submission> cohort = readZip(entries("s/handin/work.zip", work));

        assertThat(cohort.get(0).problem()).isNull();
        assertThat(cohort.get(0).sphere().path()).isEqualTo("handin/work.zip!/src/Sphere.java");
        assertThat(text(cohort.get(0).renderer())).isEqualTo(RENDERER);
    }

    @Test
    void aZipInsideTheStudentsZipIsNotOpenedAndTheProblemSaysSo() throws IOException {
        byte[] inner = zip(entries("Sphere.java", SPHERE, "Renderer.java", RENDERER));
        byte[] outer = zip(entries("inner.zip", inner));
        List<Submission> cohort = readZip(entries("s/work.zip", outer));

        assertThat(cohort.get(0).problem())
                .isEqualTo("no Sphere.java or Renderer.java in the submission (work.zip!/inner.zip is a zip inside a "
                        + "zip, which tick1 does not open)");
    }

    @Test
    void aMissingFileIsTheStudentsProblem() throws IOException {
        List<Submission> cohort = readZip(entries("s/Sphere.java", SPHERE));

        assertThat(cohort.get(0).problem()).isEqualTo("no Renderer.java in the submission");
        assertThat(cohort.get(0).files()).isEmpty();
    }

    @Test
    void twoCandidatesForOneFileAreAProblemNamingBoth() throws IOException {
        List<Submission> cohort = readZip(entries("s/old/Sphere.java", SPHERE, "s/new/Sphere.java", SPHERE,
                "s/Renderer.java", RENDERER));

        assertThat(cohort.get(0).problem()).isEqualTo("two files could be Sphere.java: old/Sphere.java and "
                + "new/Sphere.java");
    }

    @Test
    void anEmptyFolderIsTheStudentsProblem() throws IOException {
        List<Submission> cohort = readZip(entries("s/", "", "s/sub/", ""));

        assertThat(cohort).singleElement().extracting(Submission::problem).isEqualTo("the folder is empty");
    }

    @Test
    void aDownloadWithoutFoldersGroupsMoodlesNamedFilesByStudent() throws IOException {
        List<Submission> cohort = readZip(entries("Ann Lee_7_assignsubmission_file_Sphere.java", SPHERE,
                "Ann Lee_7_assignsubmission_file_Renderer.java", RENDERER));

        assertThat(cohort).singleElement().satisfies(s -> {
            assertThat(s.folder()).isEqualTo("Ann Lee_7_assignsubmission_file_");
            assertThat(s.id()).isEqualTo("7");
            assertThat(s.sphere().path()).isEqualTo("Sphere.java");
            assertThat(s.problem()).isNull();
        });
    }

    @Test
    void anyOtherLooseFileAtTheTopIsASubmissionWithAProblem() throws IOException {
        List<Submission> cohort = readZip(entries("README.txt", "hi", ".DS_Store", "x", "__MACOSX/s/._x", "x",
                "s/Sphere.java", SPHERE, "s/Renderer.java", RENDERER));

        assertThat(cohort).hasSize(2).first().satisfies(s -> {
            assertThat(s.folder()).isEqualTo("README.txt");
            assertThat(s.problem()).isEqualTo("README.txt is a file at the top of the download, not in a student's "
                    + "folder");
        });
    }

    @Test
    void moodlesFoldersAndFilesOfOtherSubmissionTypesArePassedOver() throws IOException {
        List<Submission> cohort = readZip(entries("Ann_7_assignsubmission_onlinetext_/onlinetext.html", "<p>hi</p>",
                "Bob_8_assignsubmission_onlinetext_onlinetext.html", "<p>hi</p>",
                "Cy_9_assignsubmission_file/Sphere.java", SPHERE,
                "Cy_9_assignsubmission_file/Renderer.java", RENDERER));

        assertThat(cohort).extracting(Submission::id).containsExactly("9");
    }

    @Test
    void aDownloadWithNoSubmissionsIsRefusedAsAWhole() throws IOException {
        Path download = write("cohort.zip", zip(entries("Ann_7_assignsubmission_onlinetext_/onlinetext.html",
                "<p>hi</p>")));

        assertThatThrownBy(() -> Submissions.read(download)).isInstanceOf(CohortInputException.class)
                .hasMessage(download + ": no submissions: the download holds no student's folder of files");
    }

    @Test
    void anEmptyFolderGivenAsTheDownloadIsRefused() throws IOException {
        Path download = Files.createDirectory(temp.resolve("download"));

        assertThatThrownBy(() -> Submissions.read(download)).isInstanceOf(CohortInputException.class)
                .hasMessage(download + ": no submissions: the download holds no student's folder of files");
    }

    @Test
    void theFolderHoldingTheDownloadsZipIsRefusedNamingTheZip() throws IOException {
        Path parent = Files.createDirectory(temp.resolve("Downloads"));
        Files.write(parent.resolve("Tick 1-1234.zip"), zip(entries("Ann_7_assignsubmission_file/Sphere.java",
                SPHERE, "Ann_7_assignsubmission_file/Renderer.java", RENDERER)));
        Files.writeString(parent.resolve("notes.txt"), "to do");

        assertThatThrownBy(() -> Submissions.read(parent)).isInstanceOf(CohortInputException.class)
                .hasMessage(parent + ": no submissions: it holds no student's folder, only files (Tick "
                        + "1-1234.zip and notes.txt); --submissions wants the download itself: " + parent.resolve(
                                "Tick 1-1234.zip"));
    }

    @Test
    void theFolderHoldingTheUnpackedDownloadIsRefusedNamingIt() throws IOException {
        Path parent = Files.createDirectory(temp.resolve("Downloads"));
        Path unpacked = Files.createDirectories(parent.resolve("Tick 1-1234").resolve("Ann_7_assignsubmission_file"));
        Files.writeString(unpacked.resolve("Sphere.java"), SPHERE);
        Files.writeString(unpacked.resolve("Renderer.java"), RENDERER);

        assertThatThrownBy(() -> Submissions.read(parent)).isInstanceOf(CohortInputException.class)
                .hasMessage(parent + ": the folder holds the download, not the students' folders; --submissions "
                        + "wants the download itself: " + parent.resolve("Tick 1-1234"));
    }

    @Test
    void aZipWhoseOneFolderHoldsTheDownloadIsRefusedNamingTheFolder() throws IOException {
        Path rezipped = write("rezipped.zip", zip(entries("Tick 1-1234/Ann_7_assignsubmission_file/Sphere.java",
                SPHERE, "Tick 1-1234/Ann_7_assignsubmission_file/Renderer.java", RENDERER)));

        assertThatThrownBy(() -> Submissions.read(rezipped)).as("a zip holding the download in a folder")
                .isInstanceOf(CohortInputException.class)
                .hasMessage(rezipped + ": the zip holds the download in its folder Tick 1-1234, not the students' "
                        + "folders; --submissions wants Moodle's zip itself, or that folder unpacked");
    }

    @Test
    void submissionsAreSortedByFolderName() throws IOException {
        List<Submission> cohort = readZip(entries("c/Sphere.java", SPHERE, "a/Sphere.java", SPHERE,
                "b/Sphere.java", SPHERE));

        assertThat(cohort).extracting(Submission::folder).containsExactly("a", "b", "c");
    }

    @Test
    void anUnpackedFolderGivesTheSameSubmissionsAsItsZip() throws IOException {
        Map<String, byte[]> entries = entries("Ann_1_assignsubmission_file_/src/Sphere.java", SPHERE,
                "Ann_1_assignsubmission_file_/src/Renderer.java", RENDERER,
                "Bob_2_assignsubmission_file_/w.zip", zip(entries("Sphere.java", SPHERE, "Renderer.java", RENDERER)),
                "Cy_3_assignsubmission_file_/Sphere.java", SPHERE);
        Path folder = Files.createDirectory(temp.resolve("unpacked"));
        for (Map.Entry<String, byte[]> entry : entries.entrySet()) {
            Path file = folder.resolve(entry.getKey());
            Files.createDirectories(file.getParent());
            Files.write(file, entry.getValue());
        }

        assertThat(describe(Submissions.read(folder))).isEqualTo(describe(readZip(entries)));
    }

    private static List<String> describe(List<Submission> cohort) {
        return cohort.stream().map(s -> s.folder() + "|" + s.id() + "|" + s.fullName() + "|" + s.problem() + "|"
                + s.files().stream().map(f -> f.path() + "=" + new String(f.content(), StandardCharsets.UTF_8))
                        .toList()).toList();
    }

    // ------------------------------------------------------------------------------------------ hostile

    @Test
    void anEntryClimbingOutOfTheFolderRefusesTheDownload() throws IOException {
        Path download = write("slip.zip", new TestZips.Raw().add("s/../../evil/Sphere.java", SPHERE).bytes());

        assertThatThrownBy(() -> Submissions.read(download)).isInstanceOf(CohortInputException.class)
                .hasMessage(download + ": entry s/../../evil/Sphere.java climbs out of the folder with .. (zip slip)");
    }

    @Test
    void anAbsoluteEntryNameRefusesTheDownload() throws IOException {
        Path download = write("abs.zip", new TestZips.Raw().add("/etc/cron.d/x", "x").bytes());

        assertThatThrownBy(() -> Submissions.read(download))
                .hasMessage(download + ": entry /etc/cron.d/x has an absolute name (zip slip)");
    }

    @Test
    void aHostileZipOfTheStudentsIsTheirProblemNotTheCohorts() throws IOException {
        byte[] slip = new TestZips.Raw().add("../Sphere.java", SPHERE).add("Renderer.java", RENDERER).bytes();
        List<Submission> cohort = readZip(entries("a/w.zip", slip, "b/Sphere.java", SPHERE,
                "b/Renderer.java", RENDERER));

        assertThat(cohort.get(0).problem())
                .isEqualTo("w.zip: entry ../Sphere.java climbs out of the folder with .. (zip slip)");
        assertThat(cohort.get(1).problem()).isNull();
    }

    @Test
    void aSymbolicLinkEntryRefusesTheDownload() throws IOException {
        Path download = write("link.zip", new TestZips.Raw().symlink("s/Sphere.java", "/etc/passwd").bytes());

        assertThatThrownBy(() -> Submissions.read(download))
                .hasMessage(download + ": entry s/Sphere.java is a symbolic link, which tick1 does not follow");
    }

    @Test
    void aSymbolicLinkInAnUnpackedFolderIsNeverFollowed() throws IOException {
        Path secret = write("Sphere.java", "secret".getBytes(StandardCharsets.UTF_8));
        Path folder = Files.createDirectories(temp.resolve("unpacked/s"));
        Files.createSymbolicLink(folder.resolve("Sphere.java"), secret);
        Files.writeString(folder.resolve("Renderer.java"), RENDERER);

        List<Submission> cohort = Submissions.read(folder.getParent());

        assertThat(cohort).singleElement().satisfies(s -> {
            assertThat(s.problem()).isEqualTo("Sphere.java is a symbolic link, which tick1 does not follow");
            assertThat(s.sphere()).isNull();
        });
    }

    @Test
    void aNameThatIsNotUtf8RefusesTheDownload() throws IOException {
        byte[] latin1 = "s/Sph\u00e8re.java".getBytes(StandardCharsets.ISO_8859_1);
        Path download = write("latin1.zip", new TestZips.Raw().add(latin1, latin1, new byte[0], false, 0, 0, 0)
                .bytes());

        assertThatThrownBy(() -> Submissions.read(download))
                .hasMessage(download + ": entry s/Sph?re.java has a name that is not UTF-8");
    }

    @Test
    void twoEntriesOfOneNameRefuseTheDownload() throws IOException {
        Path download = write("dup.zip", new TestZips.Raw().add("s/Sphere.java", SPHERE).add("s/Sphere.java", "evil")
                .bytes());

        assertThatThrownBy(() -> Submissions.read(download))
                .hasMessage(download + ": two entries are named s/Sphere.java; tick1 cannot tell which is meant");
    }

    @Test
    void aLocalHeaderThatDisagreesWithTheDirectoryRefusesTheDownload() throws IOException {
        byte[] central = "s/Sphere.java".getBytes(StandardCharsets.UTF_8);
        byte[] local = "s/Evilxx.java".getBytes(StandardCharsets.UTF_8);
        byte[] content = SPHERE.getBytes(StandardCharsets.UTF_8);
        Path download = write("two-names.zip", new TestZips.Raw().add(central, local, content, false, content.length,
                0, 0).add("s/Renderer.java", RENDERER).bytes());

        assertThatThrownBy(() -> Submissions.read(download)).hasMessage(download + ": entry s/Sphere.java has "
                + "another name in its local header; the zip's two directories disagree");
    }

    @Test
    void aHugeFileIsTheStudentsProblem() throws IOException {
        List<Submission> cohort = readZip(entries("s/Sphere.java", new byte[2 * 1024 * 1024],
                "s/Renderer.java", RENDERER));

        assertThat(cohort.get(0).problem()).isEqualTo("Sphere.java is larger than 1 MiB, far more than any "
                + "Sphere.java");
    }

    @Test
    void aBombWhoseHeaderUnderstatesItsSizeIsStoppedAtTheCap() throws IOException {
        byte[] name = "s/Sphere.java".getBytes(StandardCharsets.UTF_8);
        Path download = write("bomb.zip", new TestZips.Raw().add(name, name, new byte[8 * 1024 * 1024], true, 100, 0, 0)
                .add("s/Renderer.java", RENDERER).bytes());

        assertThat(Submissions.read(download).get(0).problem())
                .isEqualTo("Sphere.java is larger than 1 MiB, far more than any Sphere.java");
    }

    @Test
    void tooManyEntriesRefuseTheDownload() throws IOException {
        TestZips.Raw raw = new TestZips.Raw();
        for (int i = 0; i < 21; i++) {
            raw.add("s/f" + i, "");
        }
        Path download = write("many.zip", raw.bytes());

        assertThatThrownBy(() -> Submissions.read(download, SMALL))
                .hasMessage(download + ": the zip has 21 entries, more than the limit of 20");
    }

    @Test
    void moreBytesInflatedThanTheBudgetRefuseTheDownload() throws IOException {
        TestZips.Raw raw = new TestZips.Raw();
        for (int i = 0; i < 9; i++) {
            raw.add("s" + i + "/w.zip", new String(new char[60 * 1024]));
        }
        Path download = write("budget.zip", raw.bytes());

        assertThatThrownBy(() -> Submissions.read(download, SMALL)).hasMessage(download
                + ": the download inflates to more than 262144 bytes of files tick1 must read; refused as a zip bomb");
    }

    @Test
    void aStudentReadingMoreThanTheirBudgetIsTheirProblemAlone() throws IOException {
        byte[] big = new TestZips.Raw().add("filler.bin", new String(new char[60 * 1024])).bytes();
        List<Submission> cohort = Submissions.read(write("greedy.zip", zip(entries("a/1.zip", big, "a/2.zip", big,
                "a/3.zip", big, "b/Sphere.java", SPHERE, "b/Renderer.java", RENDERER))), SMALL);

        assertThat(cohort.get(0).problem()).isEqualTo("the folder holds more than 131072 bytes of zips and source "
                + "files to read");
        assertThat(cohort.get(1).problem()).isNull();
    }

    @Test
    void filesNotAskedForAreNeverInflated() throws IOException {
        List<Submission> cohort = Submissions.read(write("video.zip", zip(entries("s/Sphere.java", SPHERE,
                "s/Renderer.java", RENDERER, "s/demo.mp4", new byte[1024 * 1024]))), SMALL);

        assertThat(cohort.get(0).problem()).isNull();
    }

    @Test
    void aStudentsZipOverItsLimitIsTheirProblem() throws IOException {
        List<Submission> cohort = Submissions.read(write("big.zip", zip(entries("s/w.zip", new byte[100 * 1024]))),
                SMALL);

        assertThat(cohort.get(0).problem()).isEqualTo("w.zip is larger than 65536 bytes, the largest zip tick1 opens");
    }

    @Test
    void aFileThatIsNotAZipIsOneLineNamingIt() throws IOException {
        Path download = write("grades.zip", "\u0001 binary, not a zip\u0002".repeat(2)
                .getBytes(StandardCharsets.UTF_8));

        assertThatThrownBy(() -> Submissions.read(download)).isInstanceOf(CohortInputException.class)
                .hasMessage(download + ": not a zip (no end of central directory)");
    }

    @Test
    void aTextFileGivenAsTheDownloadIsNamedForWhatItIs() throws IOException {
        Path download = write("notes.zip", "not a zip at all, though long enough".getBytes(StandardCharsets.UTF_8));

        assertThatThrownBy(() -> Submissions.read(download)).isInstanceOf(CohortInputException.class)
                .hasMessageStartingWith(download + ": a text file, not a zip: --submissions wants");
    }

    @Test
    void plainTextWhoseLinesHaveCommasUnevenlyIsATextFileNotACsvFile() throws IOException {
        Path download = write("notes.txt", "Tick 1, week 3: hand in by Friday.\nRemember the hidden scene.\n"
                .getBytes(StandardCharsets.UTF_8));

        assertThatThrownBy(() -> Submissions.read(download)).isInstanceOf(CohortInputException.class)
                .hasMessageStartingWith(download + ": a text file, not a zip: --submissions wants");
    }

    @Test
    void aMissingDownloadIsOneLineNamingIt() {
        Path download = temp.resolve("nowhere.zip");

        assertThatThrownBy(() -> Submissions.read(download)).hasMessage(download + ": no such file or folder");
    }

    @Test
    void aNestedZipOfTwentyThousandSpheresGivesAReasonOfAFewHundredCharactersThatCountsTheRest() throws IOException {
        Object[] spheres = new Object[2 * 20_000];
        for (int i = 0; i < 20_000; i++) {
            spheres[2 * i] = "copy" + i + "/Sphere.java";
            spheres[2 * i + 1] = SPHERE;
        }
        byte[] nested = zip(entries(spheres));
        List<Submission> cohort = readZip(entries("s/work.zip", nested, "s/Renderer.java", RENDERER));

        assertThat(cohort.get(0).problem()).hasSizeLessThan(500)
                .startsWith("20,000 files could be Sphere.java: work.zip!/copy0/Sphere.java, ")
                .endsWith(" and 19,997 more");
    }

    @Test
    void misnamedFilesAreListedWithTheNamesTheTickExpects() throws IOException {
        List<Submission> cohort = readZip(entries("s/Sphere (1).java", SPHERE, "s/src/renderer.java", RENDERER));

        assertThat(cohort.get(0).problem()).isEqualTo("no Sphere.java or Renderer.java in the submission; found "
                + "Sphere (1).java and src/renderer.java, but the tick's files must be named Sphere.java and "
                + "Renderer.java exactly (letter case too)");
    }

    @Test
    void aCsvGivenAsTheDownloadSaysWhatItIsAndWhatWasExpected() throws IOException {
        Path csv = write("grades.csv", "Identifier,Full name,Grade\r\nParticipant 1,A,1.00\r\n"
                .getBytes(StandardCharsets.UTF_8));

        assertThatThrownBy(() -> Submissions.read(csv)).isInstanceOf(CohortInputException.class)
                .hasMessage(csv + ": a CSV file, not a zip: --submissions wants Moodle's \"Download all "
                        + "submissions\" zip, or the folder it unpacks to (a grading worksheet goes to --worksheet)");
    }

    @Test
    void twoFoldersWithOneParticipantIdAreEachAProblemNamingBoth() throws IOException {
        List<Submission> cohort = readZip(entries("Ann_7_assignsubmission_file_/Sphere.java", SPHERE,
                "Ann_7_assignsubmission_file_/Renderer.java", RENDERER,
                "Ann Copy_7_assignsubmission_file_/Sphere.java", SPHERE,
                "Ann Copy_7_assignsubmission_file_/Renderer.java", RENDERER,
                "Bob_8_assignsubmission_file_/Sphere.java", SPHERE, "Bob_8_assignsubmission_file_/Renderer.java",
                RENDERER));

        assertThat(Submissions.sharedIds(cohort)).containsOnlyKeys("7");
        assertThat(cohort).filteredOn(submission -> submission.id().equals("7")).hasSize(2)
                .allSatisfy(submission -> assertThat(submission.problem()).isEqualTo("participant 7 has two "
                        + "folders in the download (Ann Copy_7_assignsubmission_file_ and "
                        + "Ann_7_assignsubmission_file_): tick1 cannot tell which to grade, so it grades none of "
                        + "them"));
        assertThat(cohort).filteredOn(submission -> submission.id().equals("8")).singleElement()
                .extracting(Submission::problem).isNull();
    }
}
