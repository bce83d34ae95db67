package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.diagnosis.Diagnoser;
import gfx.tick1.command.shared.diagnosis.Diagnosis;
import gfx.tick1.command.shared.grader.grading.Grading.GradingScene;
import gfx.tick1.command.shared.grader.harness.StudentFile;
import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.command.shared.kit.StarterKit;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * Grades one submission as the course's tester does: compiles the two files with the starter
 * code and renders the grading scenes with them in the sandbox, compares each image with the
 * reference, and explains each failure. Prints what {@code tick1 grade} prints for one student,
 * writes the images of failing scenes that are not hidden, and returns the result the cohort's
 * gradebook and report are made from.
 */
public final class SubmissionGrader {

    /** Where a grade's time went: JVM starts and javac, the student's code, the comparing and images. */
    public record Phases(long compileNanos, long renderNanos, long compareNanos) {
    }

    /**
     * One submission's grade: the result, whether its images could not be written, the time by phase, how its
     * two methods behaved on the behaviour inputs (not run: {@link Behaviour#ran} false), and the compiler's errors
     * when the code did not compile (else empty).
     */
    public record Graded(StudentResult result, boolean imagesUnwritable, Phases phases, Behaviour behaviour,
            List<String> compileErrors) {

        Graded(StudentResult result, boolean imagesUnwritable, Phases phases, Behaviour behaviour) {
            this(result, imagesUnwritable, phases, behaviour, List.of());
        }
    }

    /** The cohort report's label for a pass, and for each kind of failure that is not a wrong image. */
    /** The course tester's own words for a pass. */
    public static final String CONGRATULATIONS = "Congratulations! Your code passed the tester.";

    static final String PASSED = "passed", SUBMISSION_PROBLEM = "submission problem", NOT_UTF8 = "not UTF-8",
            WRONG_PACKAGE = "wrong package", DOES_NOT_COMPILE = "does not compile", TIME_LIMIT = "time limit",
            EXCEPTION = "exception", CRASHED = "crashed or exited", UNRECOGNISED = "unrecognised mistake";

    private final Grading grading;
    private final Sandbox sandbox;
    private final StudentProcess process;
    private final Path scenes;

    /**
     * Grades with {@code process}, in {@code sandbox}, on the scenes {@link Grading#copyScenes}
     * wrote into {@code scenes}.
     */
    public SubmissionGrader(Grading grading, Sandbox sandbox, StudentProcess process, Path scenes) {
        this.grading = grading;
        this.sandbox = sandbox;
        this.process = process;
        this.scenes = scenes;
    }

    /** What one grade builds up as it goes. */
    private static final class Grade {
        final long start = System.nanoTime();
        final List<SceneResult> scenes = new ArrayList<>();
        long compileNanos, renderNanos, compareNanos;
        boolean imagesUnwritable;
        /** What the probes found, once the public scenes' run is over. */
        ProbeFindings probes = ProbeFindings.of(null);
        /** Whether the probes' lines are placed in a scene's explanation yet. */
        boolean probesShown;
        /** The label and verdict of the first image a catalogue entry explains exactly, for a row's reason. */
        String exactly;
    }

    /** The student's two files as text. */
    private record Sources(String sphere, String renderer) {
    }

    /** How compiling went, where the classes are, and when it ended. */
    private record Started(StudentProcess.Compiled compiled, Path classes, long renderStart) {
    }

    /**
     * Every scene's outcome and traced samples in grading order, what the behaviour comparison
     * found (judged while the hidden scenes render), and what the code printed.
     */
    private record Rendered(List<Outcome> outcomes, List<String> traces, CompletableFuture<ProbeFindings> probes,
            String publicPrinted) {
    }

    /**
     * Grades {@code submission}. {@code work} is an empty folder for this grade (the caller
     * deletes it), {@code images} where the images of failing scenes go; {@code out} gets the
     * tester's report, {@code err} a line when the images cannot be written.
     */
    public Graded grade(Submission submission, Path work, Path images, PrintWriter out, PrintWriter err)
            throws IOException, InterruptedException {
        Grade grade = new Grade();
        if (submission.problem() != null) {
            return failed(grade, submission, out, SUBMISSION_PROBLEM, submission.problem());
        }
        Sources code;
        try {
            code = new Sources(StudentFile.decode(submission.sphere().path(), submission.sphere().content()),
                    StudentFile.decode(submission.renderer().path(), submission.renderer().content()));
        } catch (StudentFile.NotUtf8Exception e) {
            return failed(grade, submission, out, NOT_UTF8, e.getMessage());
        }
        for (String problem : new String[] {StudentFile.packageProblem(submission.sphere().path(), code.sphere()),
                StudentFile.packageProblem(submission.renderer().path(), code.renderer())}) {
            if (problem != null) {
                return failed(grade, submission, out, WRONG_PACKAGE, problem);
            }
        }
        Path sources = writeSources(work, code);
        long phaseStart = System.nanoTime();
        Started started = start(submission, sources, work);
        grade.compileNanos = started.renderStart() - phaseStart;
        StudentProcess.Compiled compiled = started.compiled();
        if (compiled.failure() != null) {
            return failed(grade, submission, out, DOES_NOT_COMPILE, "the code could not be compiled: "
                    + compiled.failure());
        }
        if (!compiled.compiled()) {
            String heading = "the code does not compile (" + count(compiled.errors().size(), "error") + ")";
            out.println("FAILED: " + heading + ":");
            compiled.errors().forEach(out::println);
            // The first error: its words as the reason's one line, and javac's source line and the caret under it
            // kept on lines of their own, as javac printed them, for the feedback to show.
            List<String> error = compiled.errors().get(0).lines().toList();
            int quoted = error.size() >= 3 && error.get(error.size() - 1).strip().equals("^") ? error.size() - 2
                    : error.size();
            return new Graded(result(grade, submission, false, 0, DOES_NOT_COMPILE,
                    "FAILED: " + heading + ": " + String.join("\n", error.subList(0, quoted)),
                    error.subList(quoted, error.size())), false, phases(grade), grade.probes.behaviour(),
                    List.copyOf(compiled.errors()));
        }
        out.println("Compiled " + submission.sphere().path() + " and " + submission.renderer().path()
                + " with the starter code.");
        Rendered rendered = renderAll(started, work);
        long compareStart = System.nanoTime();
        grade.renderNanos = compareStart - started.renderStart();
        grade.probes = rendered.probes().join();
        Graded graded = compare(grade, submission, code, rendered, images, out, err);
        return graded;
    }

    /** The two files and the starter kit's others in {@code work}/sources, shared with the sandbox. */
    private Path writeSources(Path work, Sources code) throws IOException {
        Path sources = Files.createDirectory(work.resolve("sources"));
        Files.writeString(sources.resolve("Sphere.java"), code.sphere(), StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("Renderer.java"), code.renderer(), StandardCharsets.UTF_8);
        for (String given : StarterKit.GIVEN_CLASSES) {
            Files.writeString(sources.resolve(given + ".java"), StarterKit.source(given), StandardCharsets.UTF_8);
        }
        sandbox.share(work, false);
        return sources;
    }

    /**
     * Compiles, in a JVM that runs none of the student's code (a cohort job's warm compiler, or a
     * JVM of its own), into a folder of the grader's that every later run is given read-only: so
     * that nothing a run of the code writes reaches the next run, the hidden scenes' above all.
     */
    private Started start(Submission submission, Path sources, Path work) throws IOException, InterruptedException {
        Path compiledFolder = childFolder(work, "compiled");
        StudentProcess.Compiled compiled = process.compile(sources, compiledFolder, submission.sphere().path(),
                submission.renderer().path(), grading.limits().timeLimit());
        Path classes = compiledFolder.resolve(StudentHarness.CLASSES_FOLDER);
        if (compiled.compiled()) {
            sandbox.share(classes, false);
        }
        return new Started(compiled, classes, System.nanoTime());
    }

    /**
     * Runs the public scenes (with the probes), then the hidden ones in a JVM of their own, so that
     * what the student's code prints while it has a hidden scene open is never shown. All within
     * the one time limit.
     */
    private Rendered renderAll(Started started, Path work) throws IOException, InterruptedException {
        Grading.Limits limits = grading.limits();
        long deadline = started.renderStart() + limits.timeLimit().toNanos();
        List<Outcome> outcomes = new ArrayList<>();
        List<String> traces = new ArrayList<>();
        CompletableFuture<ProbeFindings> probes = null;
        String publicPrinted = "";
        for (boolean hidden : new boolean[] {false, true}) {
            List<GradingScene> batch = grading.batch(hidden);
            if (batch.isEmpty()) {
                continue;
            }
            Duration left = Duration.ofNanos(deadline - System.nanoTime());
            if (left.toMillis() < 1) {
                batch.forEach(scene -> outcomes.add(new Outcome.Failed(
                        "not rendered: the time limit was used up by the earlier scenes")));
                batch.forEach(scene -> traces.add(null));
                continue;
            }
            StudentProcess.Result result = process.render(started.classes(), new StudentProcess.Batch(
                    Grading.batchScenes(scenes, hidden), sceneFiles(batch.size()), limits.width(), limits.height(),
                    !hidden), childFolder(work, (hidden ? "hidden" : "public") + "-run"), left, limits.timeLimit());
            outcomes.addAll(result.outcomes());
            traces.addAll(result.traces());
            if (!hidden) {
                publicPrinted = result.outputTail();
                // The answers are judged in the grader while the hidden scenes render in their own JVM.
                String log = result.probes();
                probes = CompletableFuture.supplyAsync(() -> ProbeFindings.of(log));
            }
        }
        return new Rendered(outcomes, traces, probes == null ? CompletableFuture.completedFuture(ProbeFindings.of(null))
                : probes, publicPrinted);
    }

    /** Compares every scene's outcome, then gives the verdict with its reasons. */
    private Graded compare(Grade grade, Submission submission, Sources code, Rendered rendered,
            Path images, PrintWriter out, PrintWriter err) {
        long compareStart = System.nanoTime();
        List<GradingScene> ordered = new ArrayList<>(grading.batch(false));
        ordered.addAll(grading.batch(true));
        int failures = 0;
        String diagnosis = null;
        boolean crashed = false;
        for (int i = 0; i < ordered.size(); i++) {
            GradingScene scene = ordered.get(i);
            String label;
            if (rendered.outcomes().get(i) instanceof Outcome.Failed failedScene) {
                crashed = true;
                label = notRendered(grade, scene, failedScene, out);
            } else {
                label = checkImage(grade, i + 1, scene, ((Outcome.Rendered) rendered.outcomes().get(i)).image(),
                        rendered.traces().get(i), images, out, err);
            }
            if (label != null) {
                failures++;
                diagnosis = diagnosis == null ? label : diagnosis;
            }
        }
        String printed = rendered.publicPrinted();
        if (crashed && !printed.isBlank()) {
            out.println("The last lines the code printed (while rendering the scenes that are not hidden):");
            printed.lines().skip(Math.max(0, printed.lines().count() - 5)).forEach(line -> out.println("  " + line));
        }
        grade.compareNanos = System.nanoTime() - compareStart;
        return verdict(grade, submission, ordered.size(), failures, diagnosis, out);
    }

    /** A scene the code gave no image for: why; for a hidden scene, a {@link HiddenVerdict}'s fixed words. */
    private static String notRendered(Grade grade, GradingScene scene, Outcome.Failed failedScene, PrintWriter out) {
        String reason = scene.hidden() ? HiddenVerdict.ofNoImage(failedScene.reason()).words() : failedScene.reason();
        out.println(scene.name() + ": FAIL: " + indent(reason));
        grade.scenes.add(new SceneResult(scene.name(), scene.hidden(), false, reason.lines().toList(),
                null, null, null));
        return reason.contains("time limit") ? TIME_LIMIT : reason.startsWith("the code threw") ? EXCEPTION : CRASHED;
    }

    /** The verdict line, the notes of a pass, and the result with its row's reason. */
    private Graded verdict(Grade grade, Submission submission, int scenes, int failures, String diagnosis,
            PrintWriter out) {
        if (failures > 0) {
            String verdict = "FAILED: " + failures + " of " + count(scenes, "scene") + " wrong.";
            out.println(verdict);
            return new Graded(result(grade, submission, false, scenes - failures, diagnosis,
                    verdict + reasons(grade)), grade.imagesUnwritable, phases(grade), grade.probes.behaviour());
        }
        out.println(CONGRATULATIONS);
        List<String> notes = grade.probes.notes();
        notes.forEach(note -> out.println("Note: " + note));
        if (!notes.isEmpty() && !grade.scenes.isEmpty()) {
            // The notes live in the explanation of the first scene, whose run made them.
            SceneResult first = grade.scenes.get(0);
            grade.scenes.set(0, new SceneResult(first.name(), first.hidden(), true,
                    notes.stream().map(note -> "note: " + note).toList(), null, null, null));
        }
        String reason = notes.isEmpty() ? CONGRATULATIONS : CONGRATULATIONS + " Note: " + String.join("; ", notes)
                + ".";
        return new Graded(result(grade, submission, true, scenes, PASSED, reason), false, phases(grade),
                grade.probes.behaviour());
    }

    /** A submission that fails before any scene is run: one line saying why. */
    private Graded failed(Grade grade, Submission submission, PrintWriter out, String diagnosis,
            String reason) {
        out.println("FAILED: " + reason);
        return new Graded(result(grade, submission, false, 0, diagnosis, "FAILED: " + reason), false, phases(grade),
                grade.probes.behaviour());
    }

    private StudentResult result(Grade grade, Submission submission, boolean passed, int scenesPassed,
            String diagnosis, String reason) {
        return result(grade, submission, passed, scenesPassed, diagnosis, reason, List.of());
    }

    /** The result, whose reason is {@code reason} as one line, then the {@code quoted} lines as they are. */
    private StudentResult result(Grade grade, Submission submission, boolean passed, int scenesPassed,
            String diagnosis, String reason, List<String> quoted) {
        StringBuilder text = new StringBuilder(oneLine(reason));
        quoted.forEach(line -> text.append('\n').append(line));
        return new StudentResult(submission, passed, scenesPassed, grade.scenes.isEmpty() ? 0 : grading.scenes().size(),
                diagnosis, text.toString(), List.copyOf(grade.scenes),
                Duration.ofNanos(System.nanoTime() - grade.start));
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

    private static Phases phases(Grade grade) {
        return new Phases(grade.compileNanos, grade.renderNanos, grade.compareNanos);
    }

    /**
     * A failure's reasons for the gradebook's row, in one sentence: the scenes that gave no image
     * or an image their code does not give, by their first lines; then the catalogue's exact image
     * match; then the tested findings; failing both, that tick1 does not recognise it. A hidden
     * scene is "hidden scene N", as on the feedback page: its file name may tell what it holds.
     */
    private static String reasons(Grade grade) {
        StringBuilder text = new StringBuilder();
        int hidden = 0;
        boolean wrongImage = false;
        for (SceneResult scene : grade.scenes) {
            String name = scene.hidden() ? "hidden scene " + ++hidden : scene.name();
            if (scene.passed()) {
                continue;
            }
            if (scene.explanation().stream().anyMatch(line -> line.startsWith("mean difference")
                    || line.equals(HiddenVerdict.WRONG.words()))) {
                wrongImage = true;
                continue;
            }
            text.append(' ').append(name).append(": ").append(scene.explanation().get(0)).append('.');
        }
        if (wrongImage && grade.exactly != null) {
            text.append(' ').append(grade.exactly);
        }
        if (grade.probes.anyFailed()) {
            text.append(' ').append(grade.probes.sentence());
        } else if (wrongImage && grade.exactly == null) {
            text.append(' ').append(grade.probes.ran() ? UNSURE_WITH_PROBES : UNSURE_WITHOUT_PROBES);
        }
        return text.toString().replace("..", ".");
    }

    /** Why a wrong image has no cause to name, when both methods behave as ours. */
    static final String UNSURE_WITH_PROBES = "Your intersectionWith and illuminate behave as ours on every input "
            + "tick1 tried, and no mistake of its catalogue gives this image, so tick1 does not recognise what makes "
            + "the difference.";
    /** Why a wrong image has no cause to name, when the methods could not be run on their own. */
    static final String UNSURE_WITHOUT_PROBES = "Your intersectionWith and illuminate could not be run on their own "
            + "inputs, and no mistake of tick1's catalogue gives this image, so tick1 does not recognise what makes "
            + "the difference.";

    /**
     * Compares one student image with the references --reference allows, and, when it matches,
     * with what their own methods give for the sampled pixels; explains a difference, and, for a
     * scene that is not hidden, writes the images.
     *
     * @return null for a pass, else the label of the failure for the cohort's chart
     */
    private String checkImage(Grade grade, int number, GradingScene scene, BufferedImage image, String trace,
            Path images, PrintWriter out, PrintWriter err) {
        ReferenceChoice choice = grading.limits().referenceChoice();
        BufferedImage handout = choice == ReferenceChoice.robust ? null
                : grading.reference(scene, Intersection.HANDOUT);
        BufferedImage robust = choice == ReferenceChoice.handout ? null
                : grading.reference(scene, Intersection.ROBUST);
        boolean handoutMatched = handout != null && samePixels(handout, image);
        boolean robustMatched = robust != null && samePixels(robust, image);
        boolean referencesAgree = handout != null && robust != null && samePixels(handout, robust);
        if (handoutMatched || robustMatched) {
            SampleCheck.Result check = SampleCheck.check(image, trace);
            if (check != SampleCheck.Result.AGREES) {
                return notFromTheCode(grade, scene, check, out);
            }
            if (scene.hidden()) {
                // Which reference it matched is the code's to choose, on a scene where the two differ.
                out.println(scene.name() + ": " + HiddenVerdict.PASS.words());
                grade.scenes.add(new SceneResult(scene.name(), true, true, List.of(), null, null, null));
                return null;
            }
            String which = "the reference", other = "";
            if (handout != null && robust != null && !referencesAgree) {
                which = handoutMatched ? "the handout-arithmetic reference" : "the robust reference";
                other = "; the " + (handoutMatched ? "robust" : "handout-arithmetic")
                        + " reference differs on this scene";
            }
            out.println(scene.name() + ": PASS (identical to " + which + ", "
                    + image.getWidth() * image.getHeight() + " pixels" + other + ")");
            grade.scenes.add(new SceneResult(scene.name(), scene.hidden(), true, List.of(), null, null, null));
            return null;
        }
        if (scene.hidden()) {
            return wrongHiddenImage(grade, scene, out);
        }
        // Explain against the closer reference.
        ImageDifference toHandout = handout == null ? null : ImageDifference.between(handout, image);
        ImageDifference toRobust = robust == null ? null : ImageDifference.between(robust, image);
        boolean againstHandout = toRobust == null
                || toHandout != null && toHandout.differingPixels() < toRobust.differingPixels();
        ImageDifference difference = againstHandout ? toHandout : toRobust;
        List<String> lines = new ArrayList<>();
        lines.add(difference.summary());
        if (handout != null && robust != null && !referencesAgree) {
            lines.add("(compared with the " + (againstHandout ? "handout-arithmetic" : "robust")
                    + " reference, the closer of the two, which differ on this scene)");
        }
        String label = explain(grade, scene, image, difference, lines);
        out.println(scene.name() + ": FAIL: " + lines.get(0));
        lines.subList(1, lines.size()).forEach(line -> out.println("  " + line));
        writeImages(grade, number, scene, image, difference, againstHandout ? handout : robust, lines, images, out,
                err);
        return label;
    }

    /** Why a matching image fails: their own methods give other colours, or could not be asked. */
    private static String notFromTheCode(Grade grade, GradingScene scene, SampleCheck.Result check, PrintWriter out) {
        String reason = check == SampleCheck.Result.DISAGREES ? NOT_FROM_THE_CODE + ": traced through your own "
                + "intersectionWith and illuminate, its sampled pixels have other colours"
                : NOT_FROM_THE_CODE + "? Its sampled pixels could not be traced through your intersectionWith and "
                + "illuminate (they did not return in time, or the harness's record of them is missing)";
        String shown = scene.hidden() ? HiddenVerdict.NOT_FROM_THE_CODE.words() : reason;
        out.println(scene.name() + ": FAIL: " + shown);
        grade.scenes.add(new SceneResult(scene.name(), scene.hidden(), false, List.of(shown), null, null, null));
        return NOT_FROM_CODE_LABEL;
    }

    /**
     * A hidden scene's wrong image: the fixed verdict, and no figure, diagnosis or image of it
     * (each is the code's to choose). The behaviour comparison's findings and notes follow, if no
     * earlier scene showed them: its inputs are fixed and ran in the run of the public scenes, which
     * never had a hidden one, so they carry nothing of it. The chart's label is the first tested
     * finding's, or that the mistake is not recognised.
     */
    private static String wrongHiddenImage(Grade grade, GradingScene scene, PrintWriter out) {
        List<String> lines = new ArrayList<>(List.of(HiddenVerdict.WRONG.words()));
        if (!grade.probesShown && (grade.probes.anyFailed() || !grade.probes.untested().isEmpty())) {
            lines.addAll(grade.probes.failureLines());
            grade.probesShown = true;
        }
        out.println(scene.name() + ": FAIL: " + lines.get(0));
        lines.subList(1, lines.size()).forEach(line -> out.println("  " + line));
        grade.scenes.add(new SceneResult(scene.name(), true, false, lines, null, null, null));
        return grade.probes.anyFailed() ? grade.probes.label() : UNRECOGNISED;
    }

    /** The words of a matching image that their methods do not give. */
    public static final String NOT_FROM_THE_CODE = "the image does not come from your Sphere and Renderer";
    static final String NOT_FROM_CODE_LABEL = "image not from the code";

    /**
     * The figures and the diagnosis of a wrong image, then the failed probes (the first wrong image
     * only) and what to reread; the label for the cohort's chart.
     */
    private static String explain(Grade grade, GradingScene scene, BufferedImage image, ImageDifference difference,
            List<String> lines) {
        double[] mean = difference.meanPerChannel();
        lines.add(String.format("mean difference R %.3f, G %.3f, B %.3f levels; PSNR %.2f dB", mean[0], mean[1],
                mean[2], difference.psnr()));
        Diagnosis diagnosis = new Diagnoser().diagnose(image, scene.scene());
        boolean exact = diagnosis.verdict() == Diagnosis.Verdict.EXPLAINED;
        boolean behaviourSays = grade.probes.anyFailed();
        // What to reread comes from the tested findings; the image's own entry only when it matches exactly.
        diagnosis.report().stream().filter(line -> !line.startsWith("reread:") || exact && !behaviourSays)
                .forEach(lines::add);
        if (!grade.probesShown && (behaviourSays || !grade.probes.untested().isEmpty())) {
            lines.addAll(grade.probes.failureLines());
            grade.probesShown = true;
        } else if (!behaviourSays && !exact) {
            lines.add(grade.probes.noFindingLine());
        }
        if (exact && grade.exactly == null) {
            grade.exactly = (scene.hidden() ? "A hidden scene" : scene.name()) + " is exactly the image of \""
                    + diagnosis.explaining().get(0).variant().title() + "\".";
        }
        // The chart counts exact matches first, then tested findings; never what the scenes cannot show.
        return exact ? diagnosis.explaining().get(0).variant().title()
                : behaviourSays ? grade.probes.label() : UNRECOGNISED;
    }

    /** Writes the images of a scene that is not hidden (a hidden one has none): heat map, theirs, the reference. */
    private void writeImages(Grade grade, int number, GradingScene scene, BufferedImage image,
            ImageDifference difference, BufferedImage expected, List<String> lines, Path images, PrintWriter out,
            PrintWriter err) {
        String stem = number + "-" + scene.name().replaceAll("[^A-Za-z0-9._-]", "_").replaceAll("\\.xml$", "");
        String heatMap = stem + "-diff.png", yours = stem + "-yours.png", reference = stem + "-expected.png";
        try {
            Files.createDirectories(images);
            PngOutput.write(difference.signedHeatMapWithLegend(), images.resolve(heatMap));
            PngOutput.write(image, images.resolve(yours));
            PngOutput.write(expected, images.resolve(reference));
            out.println("  heat map: " + images.resolve(heatMap) + " (beside it: " + yours + " and " + reference + ")");
            grade.scenes.add(new SceneResult(scene.name(), false, false, lines, heatMap, yours, reference));
        } catch (IOException e) {
            err.println("tick1 grade: " + images + ": cannot write the report images: " + IoErrors.describe(e));
            grade.imagesUnwritable = true;
            grade.scenes.add(new SceneResult(scene.name(), false, false, lines, null, null, null));
        }
    }

    /** Whether two images of the same size have the same pixels: the pass path needs no difference figures. */
    private static boolean samePixels(BufferedImage a, BufferedImage b) {
        if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) {
            return false;
        }
        int[] first = pixels(a), second = pixels(b);
        return Arrays.equals(first, second);
    }

    private static int[] pixels(BufferedImage image) {
        if (image.getType() == BufferedImage.TYPE_INT_RGB
                && image.getRaster().getDataBuffer() instanceof DataBufferInt ints
                && ints.getNumBanks() == 1 && ints.getData().length == image.getWidth() * image.getHeight()) {
            return ints.getData();
        }
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }

    /** An empty folder for the student's process to write in. */
    private Path childFolder(Path work, String name) throws IOException {
        Path folder = Files.createDirectory(work.resolve(name));
        sandbox.share(folder, true);
        return folder;
    }

    /** The names the scenes of a batch have inside the sandbox: 0.xml, 1.xml, ... */
    private static List<String> sceneFiles(int count) {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            names.add(i + ".xml");
        }
        return names;
    }

    private static String indent(String text) {
        return text.replace("\n", "\n    ");
    }

    public static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }
}
