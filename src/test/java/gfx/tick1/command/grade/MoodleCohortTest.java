package gfx.tick1.command.grade;

import static gfx.tick1.command.grade.GradeCohortTest.WORKSHEET_HEADER;
import static gfx.tick1.command.grade.GradeCohortTest.gradeArguments;
import static gfx.tick1.command.grade.GradeCohortTest.rows;
import static gfx.tick1.command.grade.GradeCohortTest.worksheetRow;
import static gfx.tick1.command.grade.GradeCohortTest.zip;
import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * {@code tick1 grade --submissions} on downloads whose names decide whose row of grades.csv a grade fills, named as
 * Moodle names them ({@link MoodleNaming}). Each cohort here has only submissions with a problem in their files, so
 * nothing is run in the sandbox.
 */
@ExtendWith(SandboxNeeded.class)
class MoodleCohortTest {

    @Test
    void aStudentsOwnFileNameNeverFillsAnotherParticipantsRow(@TempDir Path dir) throws IOException {
        // A download without folders: participant 66 uploads correct files named as if they were 88's, who
        // submitted nothing.
        StudentSolution correct = StudentSolution.correct();
        Path download = Files.write(dir.resolve("flat.zip"), zip(Map.of(
                MoodleNaming.looseFile("Mallory", 66, "X_88_assignsubmission_file_Sphere.java"),
                correct.sphere().getBytes(StandardCharsets.UTF_8),
                MoodleNaming.looseFile("Mallory", 66, "X_88_assignsubmission_file_Renderer.java"),
                correct.renderer().getBytes(StandardCharsets.UTF_8))));
        Path worksheet = Files.writeString(dir.resolve("w.csv"), WORKSHEET_HEADER + "\r\n"
                + worksheetRow(66, "Mallory", "10.00") + worksheetRow(88, "Victim", "10.00"));
        Path report = dir.resolve("report");
        CliRun run = CliRun.of(gradeArguments(download, report, "--worksheet", worksheet.toString()));

        Map<String, List<String>> rows = rows(report);
        assertThat(rows.get("Participant 88")).as("the grade of 88, who submitted nothing").element(4)
                .isEqualTo("");
        assertThat(run.err()).as("88 has no submission").contains("Participant 88 (Victim) has no submission");
        assertThat(rows.get("Participant 66").get(9)).as("66's feedback").contains("X_88_assignsubmission_file_");
    }

    @Test
    void aNameMoodleDoesNotMakeIsOneLineOnStandardErrorAndNoRowOfGradesCsv(@TempDir Path dir) throws IOException {
        byte[] sphere = StudentSolution.correct().sphere().getBytes(StandardCharsets.UTF_8);
        // Neither has a Renderer.java, so nothing is run: a problem of their files.
        Path download = Files.write(dir.resolve("a.zip"), zip(Map.of(MoodleNaming.folder("Ann Lee", 7)
                + "/Sphere.java", sphere, "ab123/Sphere.java", sphere)));
        Path report = dir.resolve("report");
        CliRun run = CliRun.of(gradeArguments(download, report));

        assertThat(run.err().lines().filter(line -> line.contains("ab123"))).as(run.transcript()).singleElement()
                .asString().isEqualTo("tick1 grade: ab123: not a name Moodle gives a student's folder or file "
                        + "(Full Name_<participant id>_assignsubmission_file): graded in the report, but given no "
                        + "row in grades.csv");
        assertThat(rows(report)).as("grades.csv's rows").containsOnlyKeys("Participant 7");
        assertThat(Files.readString(report.resolve("index.html"))).as("the report").contains("ab123");
    }
    @Test
    void aNameLongerThanTheFileSystemTakesStopsNothing(@TempDir Path dir) throws IOException {
        byte[] sphere = StudentSolution.correct().sphere().getBytes(StandardCharsets.UTF_8);
        String longName = "陈".repeat(100);
        // No Renderer.java, so nothing is run: a problem of the files.
        Path download = Files.write(dir.resolve("a.zip"), zip(Map.of(MoodleNaming.folder(longName, 4242)
                + "/Sphere.java", sphere)));
        Path report = dir.resolve("report");
        CliRun run = CliRun.of(gradeArguments(download, report));

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(rows(report)).as("grades.csv's rows").containsOnlyKeys("Participant 4242");
        assertThat(report.resolve("feedback.zip")).isRegularFile();
        assertThat(report.resolve("index.html")).isRegularFile();
    }
}
