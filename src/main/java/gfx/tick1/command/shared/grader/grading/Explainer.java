package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.behaviour.BehaviourFindings;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.grader.grading.SceneJudge.Judged;
import gfx.tick1.command.shared.grader.grading.SubmissionGrader.Graded;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.engine.io.Counted;
import java.io.PrintWriter;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * The grade's last step: the verdict line the tester prints, the gradebook row's reason and the
 * cohort's category, made from the scenes' verdicts and the behaviour comparison's findings.
 */
final class Explainer {

    /** The words of a matching image that their methods do not give. */
    static final String NOT_FROM_THE_CODE = SubmissionGrader.NOT_FROM_THE_CODE;

    /** Why a wrong image has no cause to name, when both methods behave as ours. */
    static final String UNSURE_WITH_PROBES = "Your intersectionWith and illuminate behave as ours on every input "
            + "tick1 tried, and no mistake of its catalogue gives this image, so tick1 does not recognise what makes "
            + "the difference.";
    /** Why a wrong image has no cause to name, when the methods could not be run on their own. */
    static final String UNSURE_WITHOUT_PROBES = "Your intersectionWith and illuminate could not be run on their own "
            + "inputs, and no mistake of tick1's catalogue gives this image, so tick1 does not recognise what makes "
            + "the difference.";

    private final Grading grading;
    private final Submission submission;
    private final long start;
    private final PrintWriter out;

    /** Explains the grade of {@code submission} begun at {@code start}, printing the tester's report to {@code out}. */
    Explainer(Grading grading, Submission submission, long start, PrintWriter out) {
        this.grading = grading;
        this.submission = submission;
        this.start = start;
        this.out = out;
    }

    /** A submission that fails before any scene is run: one line saying why. */
    Graded failed(Category category, String reason) {
        out.println("FAILED: " + reason);
        return new Graded(result(List.of(), false, 0, category, "FAILED: " + reason, List.of()), false,
                BehaviourFindings.of(null).behaviour());
    }

    /** Code that did not compile: the compiler's errors, or why the compiler did not finish. */
    Graded didNotCompile(StudentProcess.Compiled compiled) {
        if (compiled.failure() != null) {
            return failed(Category.Outcome.DOES_NOT_COMPILE, "the code could not be compiled: " + compiled.failure());
        }
        String heading = "the code does not compile (" + Counted.of(compiled.errors().size(), "error")
                + ")";
        out.println("FAILED: " + heading + ":");
        compiled.errors().forEach(out::println);
        // The first error: its words as the reason's one line, and javac's source line and the caret under it
        // kept on lines of their own, as javac printed them, for the feedback to show.
        List<String> error = compiled.errors().get(0).lines().toList();
        int quoted = error.size() >= 3 && error.get(error.size() - 1).strip().equals("^") ? error.size() - 2
                : error.size();
        return new Graded(result(List.of(), false, 0, Category.Outcome.DOES_NOT_COMPILE,
                "FAILED: " + heading + ": " + String.join("\n", error.subList(0, quoted)),
                error.subList(quoted, error.size())), false, BehaviourFindings.of(null).behaviour(),
                List.copyOf(compiled.errors()));
    }

    /** The last lines the code printed, when a scene gave no image and it printed any. */
    void lastLinesPrinted(List<Judged> judged, String printed) {
        if (judged.stream().anyMatch(scene -> scene.verdict() instanceof SceneVerdict.Missing) && !printed.isBlank()) {
            out.println("The last lines the code printed (while rendering the scenes that are not hidden):");
            printed.lines().skip(Math.max(0, printed.lines().count() - 5)).forEach(line -> out.println("  " + line));
        }
    }

    /** The verdict line, the notes of a pass, and the result with its row's reason. */
    Graded verdict(List<Judged> judged, BehaviourFindings probes) {
        List<SceneResult> scenes = new ArrayList<>(judged.stream().map(Judged::result).toList());
        List<Judged> failures = judged.stream().filter(scene -> !(scene.verdict() instanceof SceneVerdict.Passed))
                .toList();
        if (!failures.isEmpty()) {
            String verdict = "FAILED: " + failures.size() + " of " + Counted.of(judged.size(), "scene")
                    + " wrong.";
            out.println(verdict);
            return new Graded(result(scenes, false, judged.size() - failures.size(),
                    failures.get(0).verdict().category(), verdict + reasons(judged, probes), List.of())
                    .withFindings(found(judged)), judged.stream().anyMatch(Judged::imagesUnwritable),
                    probes.behaviour());
        }
        out.println(SubmissionGrader.CONGRATULATIONS);
        List<String> notes = probes.notes();
        notes.forEach(note -> out.println("Note: " + note));
        if (!notes.isEmpty() && !scenes.isEmpty()) {
            // The notes live in the explanation of the first scene, whose run made them.
            SceneResult first = scenes.get(0);
            scenes.set(0, new SceneResult(first.name(), first.hidden(), true,
                    notes.stream().map(note -> "note: " + note).toList(), SceneResult.Images.NONE));
        }
        String reason = notes.isEmpty() ? SubmissionGrader.CONGRATULATIONS
                : SubmissionGrader.CONGRATULATIONS + " Note: " + String.join("; ", notes) + ".";
        return new Graded(result(scenes, true, judged.size(), Category.Outcome.PASSED, reason, List.of())
                .withFindings(new Findings(null, probes.facts(), probes.untested(), List.of(), List.of())), false,
                probes.behaviour());
    }

    /** What a failure's scenes found, together: the first catalogue entry, each figure, the rest each once. */
    private static Findings found(List<Judged> judged) {
        Variant catalogued = null;
        Set<String> failed = new LinkedHashSet<>();
        Set<String> notes = new LinkedHashSet<>();
        List<String> figures = new ArrayList<>();
        Set<String> reread = new LinkedHashSet<>();
        for (Judged scene : judged) {
            Findings found = scene.found();
            catalogued = catalogued == null ? found.catalogued() : catalogued;
            failed.addAll(found.failed());
            notes.addAll(found.notes());
            figures.addAll(found.figures());
            reread.addAll(found.reread());
        }
        return new Findings(catalogued, List.copyOf(failed), List.copyOf(notes), figures, List.copyOf(reread));
    }

    /**
     * A failure's reasons for the gradebook's row, in one sentence: the scenes that gave no image
     * or an image their code does not give, by their first lines; then the catalogue's exact image
     * match; then the tested findings; failing both, that tick1 does not recognise it. A hidden
     * scene is "hidden scene N", as on the feedback page: its file name may tell what it holds.
     */
    private static String reasons(List<Judged> judged, BehaviourFindings probes) {
        StringBuilder text = new StringBuilder();
        int hidden = 0;
        boolean wrongImage = false;
        String exactly = null, pixel = null;
        for (Judged scene : judged) {
            String name = scene.result().hidden() ? "hidden scene " + ++hidden : scene.result().name();
            if (scene.verdict() instanceof SceneVerdict.WrongPixels wrong) {
                wrongImage = true;
                exactly = exactly == null ? wrong.exactly() : exactly;
                pixel = pixel == null ? wrong.pixel() : pixel;
            } else if (!(scene.verdict() instanceof SceneVerdict.Passed)) {
                text.append(' ').append(name).append(": ").append(scene.result().explanation().get(0)).append('.');
            }
        }
        if (wrongImage && exactly != null) {
            text.append(' ').append(exactly);
        }
        if (probes.anyFailed()) {
            text.append(' ').append(probes.sentence());
        } else if (wrongImage && exactly == null && pixel != null) {
            text.append(' ').append(BehaviourFindings.capitalised(pixel)).append('.');
        } else if (wrongImage && exactly == null) {
            text.append(' ').append(probes.ran() ? UNSURE_WITH_PROBES : UNSURE_WITHOUT_PROBES);
        }
        return text.toString().replace("..", ".");
    }

    /** The result, whose reason is {@code reason} as one line, then the {@code quoted} lines as they are. */
    private StudentResult result(List<SceneResult> scenes, boolean passed, int scenesPassed, Category category,
            String reason, List<String> quoted) {
        StringBuilder text = new StringBuilder(oneLine(reason));
        quoted.forEach(line -> text.append('\n').append(line));
        return new StudentResult(submission, new StudentResult.Summary(passed, scenesPassed,
                scenes.isEmpty() ? 0 : grading.scenes().size(), category, text.toString()), List.copyOf(scenes),
                Duration.ofNanos(System.nanoTime() - start));
    }

    /**
     * {@code text} with each run of white space that holds a line break made one space: in one
     * pass, as the text may be the student's (a regex such as {@code \\s*\n\\s*} backtracks over
     * a long run of spaces with no break in it, quadratically).
     */
    static String oneLine(String text) {
        StringBuilder line = new StringBuilder(text.length());
        int run = -1;
        boolean broken = false;
        for (int i = 0; i <= text.length(); i++) {
            char c = i < text.length() ? text.charAt(i) : 'x';
            if (i < text.length() && (c == ' ' || c == '\t' || c == '\n' || c == 0x0B || c == '\f' || c == '\r')) {
                run = run < 0 ? i : run;
                broken |= c == '\n';
                continue;
            }
            if (run >= 0) {
                line.append(broken ? " " : text.substring(run, i));
                run = -1;
                broken = false;
            }
            if (i < text.length()) {
                line.append(c);
            }
        }
        return line.toString();
    }
}
