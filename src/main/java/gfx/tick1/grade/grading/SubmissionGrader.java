package gfx.tick1.grade.grading;

import gfx.tick1.diagnose.Diagnoser;
import gfx.tick1.diagnose.Diagnosis;
import gfx.tick1.grade.grading.Grading.GradingScene;
import gfx.tick1.grade.harness.StudentFile;
import gfx.tick1.grade.harness.StudentHarness;
import gfx.tick1.grade.model.StudentResult.SceneResult;
import gfx.tick1.grade.model.StudentResult;
import gfx.tick1.grade.model.Submission;
import gfx.tick1.grade.sandbox.Sandbox;
import gfx.tick1.grade.sandbox.StudentProcess.Outcome;
import gfx.tick1.grade.sandbox.StudentProcess;
import gfx.tick1.image.ImageDifference;
import gfx.tick1.image.PngOutput;
import gfx.tick1.io.IoErrors;
import gfx.tick1.scene.Intersection;
import gfx.tick1.starter.StarterKit;
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

    /** One submission's grade: the result, whether its images could not be written, and the time by phase. */
    public record Graded(StudentResult result, boolean imagesUnwritable, Phases phases) {
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
        Submission.SourceFile sphere = submission.sphere(), renderer = submission.renderer();
        String sphereCode, rendererCode;
        try {
            sphereCode = StudentFile.decode(sphere.path(), sphere.content());
            rendererCode = StudentFile.decode(renderer.path(), renderer.content());
        } catch (StudentFile.NotUtf8Exception e) {
            return failed(grade, submission, out, NOT_UTF8, e.getMessage());
        }
        for (String problem : new String[] {StudentFile.packageProblem(sphere.path(), sphereCode),
                StudentFile.packageProblem(renderer.path(), rendererCode)}) {
            if (problem != null) {
                return failed(grade, submission, out, WRONG_PACKAGE, problem);
            }
        }

        Path sources = Files.createDirectory(work.resolve("sources"));
        Files.writeString(sources.resolve("Sphere.java"), sphereCode, StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("Renderer.java"), rendererCode, StandardCharsets.UTF_8);
        for (String given : StarterKit.GIVEN_CLASSES) {
            Files.writeString(sources.resolve(given + ".java"), StarterKit.source(given), StandardCharsets.UTF_8);
        }
        sandbox.share(work, false);
        Grading.Limits limits = grading.limits();
        Duration timeLimit = limits.timeLimit();
        List<GradingScene> publicScenes = grading.batch(false);

        // The public scenes and the hidden ones run separately, so that what the student's code
        // prints while it has a hidden scene open is never shown. Where the heap allows, the
        // public scenes run in the compiler's JVM: one JVM start fewer.
        Path publicOutput = childFolder(work, "public-output");
        long phaseStart = System.nanoTime();
        StudentProcess.Compiled compiled;
        StudentProcess.Result publicResult = null;
        long renderStart;
        Path classes;
        if (process.compilesAndRendersInOneRun() && !publicScenes.isEmpty()) {
            StudentProcess.CompiledAndRendered run = process.compileAndRender(sources,
                    Grading.batchScenes(scenes, false), sceneFiles(publicScenes.size()), publicOutput,
                    sphere.path(), renderer.path(), limits.width(), limits.height(), timeLimit);
            compiled = run.compiled();
            publicResult = run.rendered();
            renderStart = phaseStart + run.compileNanos();
            classes = publicOutput.resolve(StudentHarness.CLASSES_FOLDER);
        } else {
            Path compiledFolder = childFolder(work, "compiled");
            compiled = process.compile(sources, compiledFolder, sphere.path(), renderer.path(), timeLimit);
            renderStart = System.nanoTime();
            classes = compiledFolder.resolve(StudentHarness.CLASSES_FOLDER);
        }
        grade.compileNanos = renderStart - phaseStart;
        if (compiled.failure() != null) {
            grade.renderNanos = 0;
            return failed(grade, submission, out, DOES_NOT_COMPILE, "the code could not be compiled: "
                    + compiled.failure());
        }
        if (!compiled.compiled()) {
            String heading = "the code does not compile (" + count(compiled.errors().size(), "error") + ")";
            out.println("FAILED: " + heading + ":");
            compiled.errors().forEach(out::println);
            return new Graded(result(grade, submission, false, 0, DOES_NOT_COMPILE,
                    "FAILED: " + heading + ": " + compiled.errors().get(0).lines().findFirst().orElse("")),
                    false, phases(grade));
        }
        out.println("Compiled " + sphere.path() + " and " + renderer.path() + " with the starter code.");

        long deadline = renderStart + timeLimit.toNanos();
        List<Outcome> outcomes = new ArrayList<>();
        String publicPrinted = "";
        for (boolean hidden : new boolean[] {false, true}) {
            List<GradingScene> batch = grading.batch(hidden);
            if (batch.isEmpty()) {
                continue;
            }
            if (!hidden && publicResult != null) {
                outcomes.addAll(publicResult.outcomes());
                publicPrinted = publicResult.outputTail();
                continue;
            }
            Duration left = Duration.ofNanos(deadline - System.nanoTime());
            if (left.toMillis() < 1) {
                batch.forEach(scene -> outcomes.add(new Outcome.Failed(
                        "not rendered: the time limit was used up by the earlier scenes")));
                continue;
            }
            String folder = hidden ? "hidden" : "public";
            StudentProcess.Result result = process.render(classes, Grading.batchScenes(scenes, hidden),
                    sceneFiles(batch.size()), childFolder(work, folder + "-run"), limits.width(), limits.height(),
                    left, timeLimit);
            outcomes.addAll(result.outcomes());
            if (!hidden) {
                publicPrinted = result.outputTail();
            }
        }
        long compareStart = System.nanoTime();
        grade.renderNanos = compareStart - renderStart;

        HiddenScenes hiddenScenes = new HiddenScenes(classes);
        List<GradingScene> ordered = new ArrayList<>(publicScenes);
        ordered.addAll(grading.batch(true));
        int failures = 0;
        String diagnosis = null;
        boolean crashed = false;
        for (int i = 0; i < ordered.size(); i++) {
            GradingScene scene = ordered.get(i);
            Outcome outcome = outcomes.get(i);
            String label;
            if (outcome instanceof Outcome.Failed failedScene) {
                crashed = true;
                String reason = scene.hidden() ? hiddenScenes.withoutMessages(failedScene.reason())
                        : failedScene.reason();
                out.println(scene.name() + ": FAIL: " + indent(reason));
                grade.scenes.add(new SceneResult(scene.name(), scene.hidden(), false, reason.lines().toList(),
                        null, null, null));
                label = reason.contains("time limit") ? TIME_LIMIT
                        : reason.startsWith("the code threw") ? EXCEPTION : CRASHED;
            } else {
                label = checkImage(grade, i + 1, scene, ((Outcome.Rendered) outcome).image(), images, out, err);
            }
            if (label != null) {
                failures++;
                diagnosis = diagnosis == null ? label : diagnosis;
            }
        }
        if (crashed && !publicPrinted.isBlank()) {
            out.println("The last lines the code printed (while rendering the scenes that are not hidden):");
            publicPrinted.lines().skip(Math.max(0, publicPrinted.lines().count() - 5))
                    .forEach(line -> out.println("  " + line));
        }
        grade.compareNanos = System.nanoTime() - compareStart;
        if (failures > 0) {
            String verdict = "FAILED: " + failures + " of " + count(ordered.size(), "scene") + " wrong.";
            out.println(verdict);
            return new Graded(result(grade, submission, false, ordered.size() - failures, diagnosis,
                    verdict + reasons(grade.scenes)), grade.imagesUnwritable, phases(grade));
        }
        out.println(CONGRATULATIONS);
        return new Graded(result(grade, submission, true, ordered.size(), PASSED, CONGRATULATIONS),
                false, phases(grade));
    }

    /** A submission that fails before any scene is run: one line saying why. */
    private Graded failed(Grade grade, Submission submission, PrintWriter out, String diagnosis,
            String reason) {
        out.println("FAILED: " + reason);
        return new Graded(result(grade, submission, false, 0, diagnosis, "FAILED: " + reason), false, phases(grade));
    }

    private StudentResult result(Grade grade, Submission submission, boolean passed, int scenesPassed,
            String diagnosis, String reason) {
        return new StudentResult(submission, passed, scenesPassed, grade.scenes.isEmpty() ? 0 : grading.scenes().size(),
                diagnosis, oneLine(reason), List.copyOf(grade.scenes),
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
     * The failing scenes' first lines, their closest mistake and what to reread, for the gradebook's
     * comment. A hidden scene is "hidden scene N", as on the feedback page: its file name may tell
     * what it holds, and the comment goes to the student.
     */
    private static String reasons(List<SceneResult> scenes) {
        StringBuilder text = new StringBuilder();
        int hidden = 0;
        for (SceneResult scene : scenes) {
            String name = scene.hidden() ? "hidden scene " + ++hidden : scene.name();
            if (scene.passed()) {
                continue;
            }
            text.append(' ').append(name).append(": ").append(scene.explanation().get(0));
            scene.explanation().stream().filter(line -> line.startsWith("closest: ") || line.startsWith("reread: "))
                    .forEach(line -> text.append("; ").append(line));
            text.append('.');
        }
        return text.toString().replace("..", ".");
    }

    /**
     * Compares one student image with the references --reference allows; explains the difference
     * when it matches none, and, for a scene that is not hidden, writes the images.
     *
     * @return null for a pass, else the label of the failure for the cohort's chart
     */
    private String checkImage(Grade grade, int number, GradingScene scene, BufferedImage image, Path images,
            PrintWriter out, PrintWriter err) {
        ReferenceChoice choice = grading.limits().referenceChoice();
        BufferedImage handout = choice == ReferenceChoice.robust ? null
                : grading.reference(scene, Intersection.HANDOUT);
        BufferedImage robust = choice == ReferenceChoice.handout ? null
                : grading.reference(scene, Intersection.ROBUST);
        boolean handoutMatched = handout != null && samePixels(handout, image);
        boolean robustMatched = robust != null && samePixels(robust, image);
        boolean referencesAgree = handout != null && robust != null && samePixels(handout, robust);
        if (handoutMatched || robustMatched) {
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
        // Explain against the closer reference.
        ImageDifference toHandout = handout == null ? null : ImageDifference.between(handout, image);
        ImageDifference toRobust = robust == null ? null : ImageDifference.between(robust, image);
        boolean againstHandout = toRobust == null
                || toHandout != null && toHandout.differingPixels() < toRobust.differingPixels();
        ImageDifference difference = againstHandout ? toHandout : toRobust;
        BufferedImage expected = againstHandout ? handout : robust;
        List<String> lines = new ArrayList<>();
        lines.add(difference.summary());
        if (handout != null && robust != null && !referencesAgree) {
            lines.add("(compared with the " + (againstHandout ? "handout-arithmetic" : "robust")
                    + " reference, the closer of the two, which differ on this scene)");
        }
        double[] mean = difference.meanPerChannel();
        lines.add(String.format("mean difference R %.3f, G %.3f, B %.3f levels; PSNR %.2f dB", mean[0], mean[1],
                mean[2], difference.psnr()));
        Diagnosis diagnosis = new Diagnoser().diagnose(image, scene.scene());
        lines.addAll(diagnosis.report());
        String label = diagnosis.verdict() == Diagnosis.Verdict.EXPLAINED
                ? diagnosis.explaining().get(0).variant().title() : UNRECOGNISED;
        out.println(scene.name() + ": FAIL: " + lines.get(0));
        lines.subList(1, lines.size()).forEach(line -> out.println("  " + line));
        if (scene.hidden()) {
            out.println("  (a hidden scene: no images are written for it)");
            grade.scenes.add(new SceneResult(scene.name(), true, false, lines, null, null, null));
            return label;
        }
        String stem = number + "-" + scene.name().replaceAll("[^A-Za-z0-9._-]", "_").replaceAll("\\.xml$", "");
        String heatMap = stem + "-diff.png", yours = stem + "-yours.png", reference = stem + "-expected.png";
        try {
            Files.createDirectories(images);
            PngOutput.write(difference.heatMapWithLegend(), images.resolve(heatMap));
            PngOutput.write(image, images.resolve(yours));
            PngOutput.write(expected, images.resolve(reference));
            out.println("  heat map: " + images.resolve(heatMap) + " (beside it: " + yours + " and " + reference + ")");
            grade.scenes.add(new SceneResult(scene.name(), false, false, lines, heatMap, yours, reference));
        } catch (IOException e) {
            err.println("tick1 grade: " + images + ": cannot write the report images: " + IoErrors.describe(e));
            grade.imagesUnwritable = true;
            grade.scenes.add(new SceneResult(scene.name(), false, false, lines, null, null, null));
        }
        return label;
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
