package gfx.tick1.command.shared.grader.grading;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.behaviour.BehaviourFindings;
import gfx.tick1.command.shared.grader.grading.SceneJudge.Judged;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.NoImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A grade's category for the cohort's chart is made from the scenes' verdicts as types: what the
 * words of an explanation say cannot move a submission to another category.
 */
class SceneVerdictTest {

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "TIME_LIMIT | time limit",
        "THREW | exception",
        "MEMORY_LIMIT | crashed or exited",
        "PROCESS_LIMIT | crashed or exited",
        "DISK_LIMIT | crashed or exited",
        "ENDED | crashed or exited"})
    void aSceneWithoutAnImageIsCountedByWhyItHasNone(NoImage why, String category) {
        assertThat(new SceneVerdict.Missing(why).category().label()).as("the category of a scene that %s", why)
                .isEqualTo(category);
    }

    @Test
    void anExceptionWhoseMessageNamesTheTimeLimitIsCountedAsAnException(@TempDir Path work) throws IOException {
        Judged threw = new Judged(scene("the code threw java.lang.Error: no image within the time limit"),
                new SceneVerdict.Missing(NoImage.THREW), false, false);
        Judged wrong = new Judged(scene("a line that does not give figures"),
                new SceneVerdict.WrongPixels(new Category.Mistake("illuminate: N.L not clamped"), null), false, false);

        StudentResult result = explainer(work).verdict(List.of(threw, wrong), BehaviourFindings.of(null)).result();

        assertThat(result.diagnosis()).as("the category of the first failing scene")
                .isEqualTo(Category.Outcome.EXCEPTION);
    }

    @Test
    void aWrongImageIsKnownByItsVerdictNotByItsFigures(@TempDir Path work) throws IOException {
        Judged wrong = new Judged(scene("an explanation that does not start with the figures"),
                new SceneVerdict.WrongPixels(Category.Outcome.UNRECOGNISED, null), false, false);

        StudentResult result = explainer(work).verdict(List.of(wrong), BehaviourFindings.of(null)).result();

        assertThat(result.reason()).as("the row's reason of a wrong image tick1 does not recognise")
                .isEqualTo("FAILED: 1 of 1 scene wrong. " + Explainer.UNSURE_WITHOUT_PROBES)
                .doesNotContain("does not start with the figures");
    }

    private static SceneResult scene(String explanation) {
        return new SceneResult("tick1.xml", false, false, List.of(explanation), SceneResult.Images.NONE);
    }

    private static Explainer explainer(Path work) throws IOException {
        Grading grading = Grading.prepare(work, null,
                new Grading.Limits(16, 12, Duration.ofSeconds(10), 256, ReferenceChoice.either));
        Submission submission = new Submission("S_1_assignsubmission_file_", "1", "S", null, null, null);
        return new Explainer(grading, submission, System.nanoTime(), new PrintWriter(new StringWriter()));
    }
}
