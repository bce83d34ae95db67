package gfx.tick1.command.shared.grader.cohort;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A stored result comes back with its category and what its grade found as types, so that a second run's
 * report counts and charts them as the first run's did.
 */
class ResultStoreFindingsTest {

    private static final Submission SUBMISSION = new Submission("Bo_8_assignsubmission_file", "8", "Bo", null,
            null, null);

    @TempDir
    Path state;

    private StudentResult storedAndLoaded(StudentResult result) throws IOException {
        ResultStore store = new ResultStore(state);
        store.save("key", result, store.newEntry());
        return store.load("key", SUBMISSION);
    }

    @Test
    void aNamedMistakeAndItsFindingsComeBackAsTheyWereStored() throws IOException {
        Findings found = new Findings(Variant.FAR_ROOT, List.of("your intersectionWith gives the far root"),
                List.of("a note"), List.of("scene 1: mean difference R 1.000, G 2.000, B 3.000 levels"),
                List.of("handout section 4, steps 4 and 5."));
        StudentResult result = new StudentResult(SUBMISSION, new StudentResult.Summary(false, 0, 2,
                new Category.Mistake("far root"), "FAILED"), List.of(), Duration.ofMillis(3), found);

        StudentResult loaded = storedAndLoaded(result);

        assertThat(loaded.diagnosis()).as("the category").isEqualTo(new Category.Mistake("far root"));
        assertThat(loaded.findings()).as("what the grade found").isEqualTo(found);
    }

    @Test
    void aResultTick1CouldNotGradeIsStillNotGradedWhenLoaded() throws IOException {
        StudentResult loaded = storedAndLoaded(StudentResult.notGraded(SUBMISSION, "the grader failed"));

        assertThat(loaded.diagnosis()).as("the category").isEqualTo(Category.Outcome.NOT_GRADED);
        assertThat(loaded.graded()).as("graded").isFalse();
    }
}
