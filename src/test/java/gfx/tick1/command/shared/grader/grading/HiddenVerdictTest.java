package gfx.tick1.command.shared.grader.grading;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.sandbox.NoImage;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * What tick1 says of a hidden scene is one of a fixed set of verdicts, whatever the code did: so a
 * hidden scene can carry no more than log2 of their number bits out of the grade, and
 * docs/grading.md says how many.
 */
class HiddenVerdictTest {

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "THREW | false | the code threw java.lang.IllegalStateException: 3c 73 63 65\\n    at gfx.tick1.Renderer.leak"
            + "(Renderer.java:33) | THREW",
        "ENDED | false | the image written for this scene is unusable: the image is 2017272368 x 774976051 | NO_IMAGE",
        "ENDED | false | the program ended while rendering this scene, with exit status 120 | NO_IMAGE",
        "TIME_LIMIT | false | no image within the time limit of 10 s (an infinite loop?) | TIME_LIMIT",
        "TIME_LIMIT | false | not rendered: the time limit was used up by the earlier scenes | TIME_LIMIT",
        "ENDED | false | not rendered: the run stopped at an earlier scene | NO_IMAGE",
        "MEMORY_LIMIT | false | the program used more than 1 GiB of memory in all (all its processes) | MEMORY",
        "DISK_LIMIT | false | the program was stopped: it wrote more than 256 MiB to its output folder | OUTPUT_FOLDER",
        "THREW | true | the code threw java.lang.OutOfMemoryError\\nit reached the limit of 96 processes | PROCESSES"})
    void aSceneWithoutAnImageGetsAVerdictAndNothingOfTheReasonsFigures(NoImage why, boolean atProcessLimit,
            String reason, HiddenVerdict verdict) {
        assertThat(HiddenVerdict.ofNoImage(new Outcome.Failed(why, reason.replace("\\n", "\n"), atProcessLimit)))
                .isEqualTo(verdict);
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "THREW | the code threw gfx.tick1.Leak$a9f3: the time limit | THREW",
        "ENDED | the code threw java.lang.Error: it reached the limit of 96 processes | NO_IMAGE",
        "TIME_LIMIT | the program used more than 1 GiB of memory | TIME_LIMIT"})
    void theWordsOfAReasonDoNotChooseTheVerdict(NoImage why, String reason, HiddenVerdict verdict) {
        assertThat(HiddenVerdict.ofNoImage(new Outcome.Failed(why, reason)))
                .as("the verdict of a scene that gave no image because it %s, whose reason reads \"%s\"", why, reason)
                .isEqualTo(verdict);
    }

    @Test
    void anImageWhoseSamplesWereNotTracedIsNotSaidToBeCheckedOnThem() {
        assertThat(HiddenVerdict.ofUnconfirmedImage(SampleCheck.Result.NO_TRACE).words())
                .as("the verdict of the expected image whose sampled pixels could not be traced through the methods")
                .doesNotContain("checked on sampled pixels");
    }

    @Test
    void anImageWhoseSamplesFoundNoThreadToBeTracedInIsAtTheLimitOfProcessesAndThreads() {
        assertThat(HiddenVerdict.ofUnconfirmedImage(SampleCheck.Result.NO_THREAD))
                .as("the verdict of the expected image whose samples found no thread to be traced in")
                .isEqualTo(HiddenVerdict.PROCESSES);
    }

    @Test
    void anImageWhoseSamplesHaveOtherColoursDoesNotComeFromTheCode() {
        assertThat(HiddenVerdict.ofUnconfirmedImage(SampleCheck.Result.DISAGREES))
                .as("the verdict of the expected image whose sampled pixels the methods give other colours")
                .isEqualTo(HiddenVerdict.NOT_FROM_THE_CODE);
    }

    @Test
    void noVerdictHoldsANumber() {
        assertThat(Arrays.stream(HiddenVerdict.values()).map(HiddenVerdict::words))
                .noneMatch(words -> words.matches(".*\\d.*"));
    }

    @Test
    void theDocsPromiseExactlyTheBitsTheVerdictsCanCarry() throws IOException {
        int verdicts = HiddenVerdict.values().length;
        String docs = Files.readString(Path.of("docs/grading.md")).replaceAll("\\s+", " ");
        assertThat(docs).as("docs/grading.md's promise for a hidden scene")
                .contains("one of " + verdicts + " fixed verdicts")
                .contains(String.format(Locale.ROOT, "log2 %d = %.2f bits", verdicts,
                        Math.log(verdicts) / Math.log(2)));
    }
}
