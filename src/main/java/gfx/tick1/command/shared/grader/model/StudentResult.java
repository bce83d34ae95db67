package gfx.tick1.command.shared.grader.model;

import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;

/**
 * How one submission fared: what the cohort's gradebook, feedback files and report page say of it.
 *
 * @param submission the submission graded
 * @param summary    the verdict: passed or not, the scenes' count, the category and the reason
 * @param scenes     each grading scene's result, in grading order (empty when nothing ran)
 * @param time       the wall time the submission took to grade
 * @param findings   what the grade found, for the cohort's tallies and look-alikes
 */
public record StudentResult(Submission submission, Summary summary, List<SceneResult> scenes, Duration time,
Findings findings) {

    /**
     * The verdict on a submission.
     *
     * @param passed       every scene matched its reference
     * @param scenesPassed how many grading scenes matched
     * @param scenesTotal  how many grading scenes there were (0 when nothing could be run)
     * @param diagnosis    the category that groups failures across the cohort, for the chart of
     *                     common mistakes: an outcome ("does not compile", "time limit") or a named mistake
     * @param reason       the one-paragraph feedback for the gradebook's comment cell; a compile error's ends
     *                     with javac's source line and the caret under it, which the feedback pages keep as
     *                     they are
     */
    public record Summary(boolean passed, int scenesPassed, int scenesTotal, Category diagnosis, String reason) {
    }

    /** A result with nothing found beyond its words. */
    public StudentResult(Submission submission, Summary summary, List<SceneResult> scenes, Duration time) {
        this(submission, summary, scenes, time, Findings.NONE);
    }

    /**
     * A submission tick1 could not grade: no verdict on its code, so no mark (its row's grade stays
     * blank), and the reason says why and that staff must grade it again.
     */
    public static StudentResult notGraded(Submission submission, String why) {
        return new StudentResult(submission, new Summary(false, 0, 0, Category.Outcome.NOT_GRADED,
        "Not graded: " + why + "; the course staff must grade it again"), List.of(), Duration.ZERO);
    }

    /** This result with {@code found} as what its grade found. */
    public StudentResult withFindings(Findings found) {
        return new StudentResult(submission, summary, scenes, time, found);
    }

    /** Whether every scene matched its reference. */
    public boolean passed() {
        return summary.passed();
    }

    /** How many grading scenes matched. */
    public int scenesPassed() {
        return summary.scenesPassed();
    }

    /** How many grading scenes there were. */
    public int scenesTotal() {
        return summary.scenesTotal();
    }

    /** The category that groups failures across the cohort. */
    public Category diagnosis() {
        return summary.diagnosis();
    }

    /** The one-paragraph feedback for the gradebook's comment cell. */
    public String reason() {
        return summary.reason();
    }

    /** Whether tick1 graded the submission's code (false when its grader failed). */
    public boolean graded() {
        return diagnosis() != Category.Outcome.NOT_GRADED;
    }

    /**
     * One grading scene's result for one student.
     *
     * @param name        the scene's name (tick1.xml; a hidden scene's name is not shown to students)
     * @param hidden      a hidden scene: no images, no quoted content
     * @param passed      the student's image equals the reference
     * @param explanation the lines that explain a failure (difference figures, the diagnosis, what
     *                    to reread); empty for a pass
     * @param files       the images written for the scene in the student's feedback folder
     *                    ({@link Images#NONE} for a pass, a hidden scene, or no image)
     */
    public record SceneResult(String name, boolean hidden, boolean passed, List<String> explanation, Images files) {

        /**
         * The file names of a scene's images in the student's feedback folder, each null where there is none.
         *
         * @param heatMap  the difference heat map
         * @param yours    the student's image
         * @param expected the reference image
         */
        public record Images(String heatMap, String yours, String expected) {

            /** No image written. */
            public static final Images NONE = new Images(null, null, null);

            /** These images with each name replaced by what {@code rename} makes of it. */
            public Images map(UnaryOperator<String> rename) {
                return new Images(rename.apply(heatMap), rename.apply(yours), rename.apply(expected));
            }

            /** The images named, in the order a page shows them: heat map, yours, expected; a null is left out. */
            public List<String> named() {
                return Stream.of(heatMap, yours, expected).filter(Objects::nonNull).toList();
            }
        }
    }
}
