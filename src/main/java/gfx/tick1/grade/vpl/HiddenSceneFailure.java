package gfx.tick1.grade.vpl;

import gfx.tick1.grade.grading.SubmissionGrader;
import gfx.tick1.grade.model.StudentResult.SceneResult;

/**
 * How a hidden scene failed, in fixed words: all a VPL report says of it. A hidden scene's figures (pixels
 * that differ, the largest difference of each channel, the bounding box), its diagnosis, its candidates and
 * their shares would tell a student who evaluates again and again where its lights and spheres are; the
 * class of an exception the code threw on it would carry one bit a time out of it.
 */
enum HiddenSceneFailure {
    WRONG_IMAGE("the image is wrong"),
    NOT_FROM_THE_CODE(SubmissionGrader.NOT_FROM_THE_CODE),
    EXCEPTION("the code threw an exception"),
    TIME_LIMIT("over the time limit"),
    MEMORY_LIMIT("over the memory limit"),
    OUTPUT_LIMIT("over the limit on what the code may write"),
    NO_IMAGE("the code gave no image");

    private final String words;

    HiddenSceneFailure(String words) {
        this.words = words;
    }

    String words() {
        return words;
    }

    /**
     * The failure of {@code scene}, from its explanation's lines in the grader's own wording (the result carries
     * no failure kind of its own); what is not recognised is {@link #NO_IMAGE}, which tells nothing either.
     */
    static HiddenSceneFailure of(SceneResult scene) {
        if (scene.explanation().stream().anyMatch(line -> line.startsWith("mean difference"))) {
            return WRONG_IMAGE;
        }
        String first = scene.explanation().isEmpty() ? "" : scene.explanation().get(0);
        if (first.startsWith(SubmissionGrader.NOT_FROM_THE_CODE)) {
            return NOT_FROM_THE_CODE;
        }
        if (first.contains("(the memory limit was reached)") || first.startsWith("the program used more than")) {
            return MEMORY_LIMIT;
        }
        if (first.startsWith("the code threw")) {
            return EXCEPTION;
        }
        if (first.contains("time limit")) {
            return TIME_LIMIT;
        }
        return first.startsWith("the program was stopped: it") ? OUTPUT_LIMIT : NO_IMAGE;
    }
}
