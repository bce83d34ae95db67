package gfx.tick1.command.shared.grader.grading;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.behaviour.BehaviourFindings;
import gfx.tick1.command.shared.grader.grading.Grading.CourseScene;
import gfx.tick1.command.shared.grader.harness.SampleTrace;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.sandbox.SceneBatch;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import gfx.tick1.engine.scene.Intersection;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The chart counts an expected image by what was found of it: one that could not be checked is not "not from the
 * code".
 */
class UncheckedImageCategoryTest {

    @Test
    void theExpectedImageThatFoundNoThreadToBeTracedInIsNotCountedAsNotFromTheCode(@TempDir Path work)
            throws Exception {
        Grading grading = Grading.prepare(work, null,
                new Grading.Limits(16, 12, Duration.ofSeconds(10), 256, ReferenceChoice.either));
        List<CourseScene> scenes = grading.batch(SceneBatch.PUBLIC);
        List<Outcome> expected = scenes.stream()
                .<Outcome>map(scene -> new Outcome.Rendered(grading.reference(scene, Intersection.HANDOUT))).toList();
        List<String> noThread = scenes.stream().map(scene -> SampleTrace.NO_THREAD + "\n").toList();
        PrintWriter out = new PrintWriter(new StringWriter());
        SceneJudge judge = new SceneJudge(grading, BehaviourFindings.of(null), null,
                new FeedbackImages(work.resolve("images"), out, out), out);

        List<SceneJudge.Judged> judged = judge.judgeBatch(SceneBatch.PUBLIC,
                new SceneRuns.Ran(expected, noThread, Duration.ZERO), List.of());

        assertThat(judged.get(0).verdict().category())
                .as("the category of the expected image whose samples found no thread to be traced in")
                .isNotEqualTo(Category.Outcome.NOT_FROM_THE_CODE);
    }
}
