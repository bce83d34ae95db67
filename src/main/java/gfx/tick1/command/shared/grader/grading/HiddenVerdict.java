package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import java.util.List;

/**
 * All that tick1 says of a hidden scene, anywhere (the one-student output, feedback.txt and
 * feedback.html, grades.csv, the cohort page): one of these verdicts, in these fixed words. The
 * student's code reads the hidden scene, so anything it chose (a pixel count, a bounding box, a
 * channel's largest difference, the catalogue entry its image matches, an exception's class or
 * message, a stack frame, an exit status, a PNG header's size, which reference it matched) could
 * carry bytes of the scene out. A verdict is all it can choose: log2 of the number of verdicts,
 * {@code log2(10)}, about 3.3 bits a hidden scene.
 */
public enum HiddenVerdict {

    PASS("PASS"),
    WRONG("wrong: the image is not the expected one"),
    NOT_FROM_THE_CODE(SubmissionGrader.NOT_FROM_THE_CODE + " (checked on sampled pixels)"),
    NOT_TRACED("the image's sampled pixels could not be traced through your Sphere and Renderer"),
    THREW("the code threw an exception"),
    TIME_LIMIT("no image within the time limit"),
    NO_IMAGE("no usable image: the program ended, or the image it wrote is unusable"),
    MEMORY("no image: the program was stopped at the memory limit"),
    PROCESSES("the program reached the limit of processes and threads"),
    OUTPUT_FOLDER("no image: the program was stopped at the limit of its output folder");

    private final String words;

    HiddenVerdict(String words) {
        this.words = words;
    }

    /** The verdict's fixed words. */
    public String words() {
        return words;
    }

    /**
     * The verdict a hidden scene's explanation states: its first line is one verdict's words, as the
     * grader wrote it. Whatever the lines hold, the answer is one of the verdicts (a failure whose
     * words are not a verdict's is {@link #NO_IMAGE}), so a report that shows only the verdict's words
     * shows nothing the code chose.
     */
    public static HiddenVerdict statedBy(List<String> explanation) {
        for (HiddenVerdict verdict : values()) {
            if (!explanation.isEmpty() && explanation.get(0).equals(verdict.words)) {
                return verdict;
            }
        }
        return NO_IMAGE;
    }

    /**
     * The verdict of a hidden scene whose image is the expected one but was not confirmed by the code's own methods,
     * from what {@code check} found.
     */
    static HiddenVerdict ofUnconfirmedImage(SampleCheck.Result check) {
        return switch (check) {
            case DISAGREES -> NOT_FROM_THE_CODE;
            case NO_THREAD -> PROCESSES;
            case NO_TRACE, AGREES -> NOT_TRACED;
        };
    }

    /**
     * The verdict of a hidden scene that gave no image, from why the run gave none. The reason's
     * words may hold the code's (an exception's message) and are not read: the kind alone decides.
     */
    static HiddenVerdict ofNoImage(Outcome.Failed failed) {
        if (failed.atProcessLimit()) {
            return PROCESSES;
        }
        return switch (failed.why()) {
            case MEMORY_LIMIT -> MEMORY;
            case DISK_LIMIT -> OUTPUT_FOLDER;
            case PROCESS_LIMIT -> PROCESSES;
            case THREW -> THREW;
            case TIME_LIMIT -> TIME_LIMIT;
            case ENDED -> NO_IMAGE;
        };
    }
}
