package gfx.tick1.command.shared.grader.model;

import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.stream.Stream;

/**
 * How one submission fared: what the cohort's gradebook, feedback files and report page say of it.
 *
 * @param submission   the submission graded
 * @param passed       every scene matched its reference
 * @param scenesPassed how many grading scenes matched
 * @param scenesTotal  how many grading scenes there were (0 when nothing could be run)
 * @param diagnosis    the category that groups failures across the cohort, for the chart of
 *                     common mistakes: an outcome ("does not compile", "time limit") or a named mistake
 * @param reason       the one-paragraph feedback for the gradebook's comment cell; a compile error's ends with
 *                     javac's source line and the caret under it, which the feedback pages keep as they are
 * @param scenes       each grading scene's result, in grading order (empty when nothing ran)
 * @param time         the wall time the submission took to grade
 * @param findings     what the grade found, for the cohort's tallies and look-alikes
 */
public record StudentResult(Submission submission, boolean passed, int scenesPassed, int scenesTotal,
        Category diagnosis, String reason, List<SceneResult> scenes, Duration time, Findings findings) {

    /** A result with nothing found beyond its words. */
    public StudentResult(Submission submission, boolean passed, int scenesPassed, int scenesTotal,
            Category diagnosis, String reason, List<SceneResult> scenes, Duration time) {
        this(submission, passed, scenesPassed, scenesTotal, diagnosis, reason, scenes, time, Findings.NONE);
    }

    /**
     * A submission tick1 could not grade: no verdict on its code, so no mark (its row's grade stays
     * blank), and the reason says why and that staff must grade it again.
     */
    public static StudentResult notGraded(Submission submission, String why) {
        return new StudentResult(submission, false, 0, 0, Category.Outcome.NOT_GRADED,
                "Not graded: " + why + "; the course staff must grade it again", List.of(), Duration.ZERO);
    }

    /** This result with {@code found} as what its grade found. */
    public StudentResult withFindings(Findings found) {
        return new StudentResult(submission, passed, scenesPassed, scenesTotal, diagnosis, reason, scenes, time, found);
    }

    /** Whether tick1 graded the submission's code (false when its grader failed). */
    public boolean graded() {
        return diagnosis != Category.Outcome.NOT_GRADED;
    }

    /**
     * One grading scene's result for one student.
     *
     * @param name        the scene's name (tick1.xml; a hidden scene's name is not shown to students)
     * @param hidden      a hidden scene: no images, no quoted content
     * @param passed      the student's image equals the reference
     * @param explanation the lines that explain a failure (difference figures, the diagnosis, what
     *                    to reread); empty for a pass
     * @param heatMap     file name of the difference heat map in the student's feedback folder, or
     *                    null (a pass, a hidden scene, or no image)
     * @param yours       file name of the student's image in that folder, or null
     * @param expected    file name of the reference image in that folder, or null
     */
    public record SceneResult(String name, boolean hidden, boolean passed, List<String> explanation,
            String heatMap, String yours, String expected) {

        /** The images named, in the order a page shows them: heat map, yours, expected; a null is left out. */
        public List<String> images() {
            return Stream.of(heatMap, yours, expected).filter(Objects::nonNull).toList();
        }
    }
}
