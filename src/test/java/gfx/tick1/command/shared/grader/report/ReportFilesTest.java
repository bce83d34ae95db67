package gfx.tick1.command.shared.grader.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Names made safe the one way the report has: what becomes a space, and that the result is always plain. */
class ReportFilesTest {

    @Test
    void moodlesFolderNamesPassUnchanged() {
        for (String name : List.of("Zoë Ünal_101_assignsubmission_file_", "Smith, John_7_assignsubmission_file_",
                "محمد_9_assignsubmission_file_")) {
            assertThat(ReportFiles.plainName(name)).as(name).isEqualTo(name);
            assertThat(ReportFiles.isPlainName(name)).as(name).isTrue();
        }
    }

    @Test
    void separatorsAndC0AndC1ControlsAndBidiMarksBecomeSpaces() {
        String name = "a/b\\c\u0000d\u001be\u0080f\u009bg\u202eh\u2066i\u200fj\u061ck";

        assertThat(ReportFiles.plainName(name)).isEqualTo("a b c d e f g h i j k");
    }

    @Test
    void aNameThatIsNothingOrADotGainsAnUnderscore() {
        assertThat(List.of("", ".", "..")).extracting(ReportFiles::plainName).containsExactly("_", "_.", "_..");
    }

    @Test
    void everyNameMadePlainIsPlainAndStaysInsideTheFeedbackFolder() {
        Path report = Path.of("/report");
        for (char c = 0; c < 0x3000; c++) {
            String plain = ReportFiles.plainName("x" + c + "y");
            assertThat(ReportFiles.isPlainName(plain)).as("U+%04X", (int) c).isTrue();
            assertThat(ReportFiles.feedbackFolder(report, plain).getParent()).isEqualTo(report.resolve("feedback"));
        }
    }

    @Test
    void aNameThatIsNotPlainIsRefusedAsAFeedbackFolder() {
        assertThatThrownBy(() -> ReportFiles.feedbackFolder(Path.of("r"), "a\u009bb"))
                .isInstanceOf(IllegalArgumentException.class);
    }
}
