package gfx.tick1.command.shared.grader.vpl;

import gfx.tick1.command.shared.grader.grading.HiddenVerdict;
import gfx.tick1.command.shared.grader.model.FindingText;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.engine.io.Counted;
import java.util.ArrayList;
import java.util.List;

/**
 * One grade in the format of VPL's evaluation (Moodle's Virtual Programming Lab, moodle-mod_vpl 4.4): one
 * comment block of titled sections, then the proposed grade as the last line. Made from the result every
 * other report of tick1 grade is made from, so it says what they say.
 *
 * <p>Every title is tick1's own words; every line below a title starts with {@code >} (see {@link VplText}),
 * so that nothing a student's code or file says can end the block, start a title or give a grade.
 */
public final class VplReport {

    /** The most compile errors shown: the first ones matter, and the report stays short. */
    static final int MOST_ERRORS = 5;
    /** The most lines of one section's text, or of one finding of a scene's explanation. */
    static final int MOST_LINES = 16;
    /** The most lines of a scene's explanation shown, each a finding: more than tick1 writes of one scene. */
    static final int MOST_FINDINGS = 24;
    /**
     * The most characters of the verdict's reason: wrapped at a space past half of {@link VplText#WIDTH}, it
     * fits in {@link #MOST_LINES} lines, so it is cut only between two findings (each is in its scene's section).
     */
    static final int MOST_REASON = VplText.WIDTH / 2 * (MOST_LINES - 1);
    /** Where the rest of a reason cut at {@link #MOST_REASON} is. */
    static final String REST = " (more below)";

    static final String BEGIN = "<|--", END = "--|>", GRADE = "Grade :=>>";
    static final String PASSED = "Tick 1: passed", FAILED = "Tick 1: failed";
    /** The title of a pass's notes: what its methods do that the course's scenes do not show. */
    static final String NOTES = "Notes: none of them changes the grade";
    /** The title of a report that proposes no grade. */
    public static final String NOT_SET_UP = "Tick 1: the tester is not set up";

    private VplReport() {
    }

    /**
     * The report of {@code result}: the verdict and its reason, each failing scene's explanation (the
     * figures, the diagnosis, what to reread; of a hidden scene, only its {@link HiddenVerdict}'s words), or
     * the compile errors; then the grade of {@code range}.
     *
     * @param compileErrors the compiler's errors when the code did not compile, each
     *                      {@code Sphere.java:L:C: error: ...} and the lines it quotes; else empty
     */
    public static String of(StudentResult result, List<String> compileErrors, GradeRange range) {
        List<String> lines = new ArrayList<>();
        lines.add(BEGIN);
        boolean hiddenOnly = failedOnlyOnHiddenScenes(result.scenes());
        lines.add(VplText.title(result.passed() ? PASSED
                : hiddenOnly ? FAILED : FAILED + ": " + result.diagnosis().label()));
        if (!compileErrors.isEmpty()) {
            lines.addAll(VplText.quoted(result.reason().substring(0, reasonHead(result.reason())), MOST_LINES));
            compileErrors.stream().limit(MOST_ERRORS).forEach(error -> lines.addAll(VplText.quoted(error,
                    MOST_LINES)));
            if (compileErrors.size() > MOST_ERRORS) {
                lines.add(">[" + (compileErrors.size() - MOST_ERRORS) + " more errors not shown]");
            }
        } else {
            lines.addAll(VplText.quoted(anyHiddenSceneFailed(result.scenes()) ? scenesWrong(result.scenes())
                    : FindingText.fitted(result.reason(), MOST_REASON, REST), MOST_LINES));
            lines.addAll(scenes(result.scenes()));
        }
        lines.add(END);
        lines.add(GRADE + range.grade(result.passed()));
        return String.join("\n", lines) + "\n";
    }

    /** How much of a compile failure's reason is its heading: up to its colon, before the first error. */
    private static int reasonHead(String reason) {
        int colon = reason.indexOf("):");
        return colon < 0 ? reason.length() : colon + 2;
    }

    /**
     * A section for each scene that failed: "tick1.xml: failed" or "hidden scene 2: failed", and why; and
     * for a pass's notes (kept in its first scene's explanation), one section of them all.
     */
    private static List<String> scenes(List<SceneResult> scenes) {
        List<String> lines = new ArrayList<>();
        int hidden = 0;
        for (SceneResult scene : scenes) {
            String name = scene.hidden() ? "hidden scene " + ++hidden : scene.name();
            if (scene.explanation().isEmpty()) {
                continue;
            }
            lines.add(VplText.title(scene.passed() ? NOTES : name + ": failed"));
            if (scene.hidden() && !scene.passed()) {
                lines.addAll(VplText.quoted(HiddenVerdict.statedBy(scene.explanation()).words(), MOST_LINES));
            } else {
                // A line of an explanation is one finding: each is quoted whole, whatever the others' length.
                scene.explanation().stream().limit(MOST_FINDINGS)
                        .forEach(line -> lines.addAll(VplText.quoted(line, MOST_LINES)));
                if (scene.explanation().size() > MOST_FINDINGS) {
                    lines.add(">[" + (scene.explanation().size() - MOST_FINDINGS) + " more lines not shown]");
                }
            }
        }
        return lines;
    }

    private static boolean anyHiddenSceneFailed(List<SceneResult> scenes) {
        return scenes.stream().anyMatch(scene -> scene.hidden() && !scene.passed());
    }

    /** The diagnosis then came from a hidden scene, and says what its image is. */
    private static boolean failedOnlyOnHiddenScenes(List<SceneResult> scenes) {
        return anyHiddenSceneFailed(scenes) && scenes.stream().allMatch(scene -> scene.hidden() || scene.passed());
    }

    /**
     * The verdict's line where a hidden scene failed: the grade's own reason speaks of every scene, and of a
     * hidden one it may name a mistake its image shows or the exception the code threw.
     */
    private static String scenesWrong(List<SceneResult> scenes) {
        long wrong = scenes.stream().filter(scene -> !scene.passed()).count();
        return "FAILED: " + wrong + " of " + Counted.of(scenes.size(), "scene") + " wrong.";
    }

    /**
     * The report where tick1 could not grade (no sandbox can be made, the scenes or the files cannot be
     * read): one comment that says so, and no grade line, so that VPL proposes no grade.
     */
    public static String notSetUp() {
        return String.join("\n", BEGIN, VplText.title(NOT_SET_UP),
                ">Your code was not run, so no grade is proposed. Please tell the course's staff: they must look at",
                ">this submission, and at what this evaluation's Compilation section says.", END) + "\n";
    }
}
