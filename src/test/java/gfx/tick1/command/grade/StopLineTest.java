package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.cohort.StoredCode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The line a stopped cohort grade ends with says only what is true of the results kept and of a rerun. */
class StopLineTest {

    @TempDir
    Path report;

    @Test
    void aStopBeforeAnyGradeOnANewReportFolderNamesNoFolderOfEarlierResults() {
        assertThat(StopLine.beforeAnyGrade(report.resolve("state"))).as("the stop line on a new report folder")
                .doesNotContain("earlier runs", report.toString());
    }

    @Test
    void aStopBeforeAnyGradeNamesTheFolderOfEarlierResultsWhereThereAreSome() throws IOException {
        Path state = Files.createDirectories(report.resolve("state").resolve("a-result"));

        assertThat(StopLine.beforeAnyGrade(state.getParent())).as("the stop line with earlier results")
                .contains("the results of earlier runs are kept in " + state.getParent());
    }

    @Test
    void aStopBeforeAnyGradeCallsNoParsedCodeEarlierResults() throws IOException {
        Path state = Files.createDirectories(report.resolve("state").resolve(StoredCode.FOLDER)).getParent();

        assertThat(StopLine.beforeAnyGrade(state)).as("the stop line with only parsed code kept")
                .doesNotContain("earlier runs");
    }

    @Test
    void aStopPartWaySaysARerunGradesTheRestWithoutCountingWhatItWouldOnlyCheckAgain() {
        assertThat(StopLine.partWay(report.resolve("state"), 2, 3)).as("the stop line with 2 of 3 kept")
                .isEqualTo("the results of 2 of 3 submissions are kept in " + report.resolve("state")
                        + "; run the same command again to grade the rest and write the report");
    }
}
