package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.behaviour.Behaviour;
import gfx.tick1.command.shared.behaviour.BehaviourFindings;
import gfx.tick1.command.shared.behaviour.PixelCounterexample;
import gfx.tick1.command.shared.grader.grading.SceneJudge.Judged;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * Grades one submission as the course's tester does: checks the two files, compiles them with the
 * starter code, renders the grading scenes with them in the sandbox, judges each image against the
 * reference, and explains each failure. Prints what {@code tick1 grade} prints for one student,
 * writes the images of failing scenes that are not hidden, and returns the result the cohort's
 * gradebook and report are made from. Each step is a class of its own: {@link SourceCheck},
 * {@link CompileStep}, {@link SceneRuns}, {@link SceneJudge} (with {@link FeedbackImages}) and
 * {@link Explainer}.
 */
public final class SubmissionGrader {

    /** Where a grade's time went: JVM starts and javac, the student's code, the comparing and images. */
    public record Phases(long compileNanos, long renderNanos, long compareNanos) {

        Phases plus(long compile, long render, long compare) {
            return new Phases(compileNanos + compile, renderNanos + render, compareNanos + compare);
        }
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

    /** The course tester's own words for a pass. */
    public static final String CONGRATULATIONS = "Congratulations! Your code passed the tester.";
    /** The words of a matching image that their methods do not give. */
    public static final String NOT_FROM_THE_CODE = "the image does not come from your Sphere and Renderer";

    /** Why a grade whose classes were too many to keep could not run its hidden scenes. */
    static final String COMPILED_ONCE_ONLY = "its classes, too many to keep while the other submissions ran, could "
            + "not be compiled again for the hidden scenes";

    private final Grading grading;
    private final Sandbox sandbox;
    private final CompileStep compiler;
    private final SceneRuns runs;

    /**
     * Grades with {@code process}, in {@code sandbox}, on the scenes {@link Grading#copyScenes}
     * wrote into {@code scenes}.
     */
    public SubmissionGrader(Grading grading, Sandbox sandbox, StudentProcess process, Path scenes) {
        this.grading = grading;
        this.sandbox = sandbox;
        this.compiler = new CompileStep(sandbox, process, grading.limits().timeLimit());
        this.runs = new SceneRuns(grading, sandbox, process, scenes);
    }

    /**
     * Grades {@code submission}. {@code work} is an empty folder for this grade (the caller
     * deletes it), {@code images} where the images of failing scenes go; {@code out} gets the
     * tester's report, {@code err} a line when the images cannot be written.
     */
    public Graded grade(Submission submission, Path work, Path images, PrintWriter out, PrintWriter err)
            throws IOException, InterruptedException {
        Begun begun = begin(submission, work, images, out, err);
        return begun instanceof Halfway halfway ? finish(halfway, work, out) : ((Finished) begun).graded();
    }

    /**
     * The first half of a grade: checks and compiles the files, runs the public scenes and the
     * probes, and judges them, printing what the tester prints for them. It ends there when the
     * code fails before any hidden scene could run; else {@link #finish} runs the hidden scenes,
     * whenever the caller chooses. A cohort begins every grade before it finishes any, so that no
     * run that a student's report quotes comes after a run that had a hidden scene, and none of
     * them can time one or feel it use the processor.
     */
    public Begun begin(Submission submission, Path work, Path images, PrintWriter out, PrintWriter err)
            throws IOException, InterruptedException {
        long start = System.nanoTime();
        Explainer explainer = new Explainer(grading, submission, start, out);
        SourceCheck.Checked checked = SourceCheck.check(submission);
        if (checked instanceof SourceCheck.Problem problem) {
            return new Finished(explainer.failed(problem.category(), problem.reason(), new Phases(0, 0, 0)));
        }
        SourceCheck.Sources sources = (SourceCheck.Sources) checked;
        CompileStep.Started started = compiler.compile(submission, sources, work);
        long compileNanos = started.renderStart() - started.compileStart();
        if (!started.compiled().compiled()) {
            return new Finished(explainer.didNotCompile(started.compiled(), new Phases(compileNanos, 0, 0)));
        }
        out.println("Compiled " + submission.sphere().path() + " and " + submission.renderer().path()
                + " with the starter code.");
        SceneRuns.PublicRun run = runs.runPublic(started, work);
        long compareStart = System.nanoTime();
        BehaviourFindings probes = run.probes().join();
        List<Judged> judged = new SceneJudge(grading, probes,
                new PixelCounterexample.Code(sources.sphere(), sources.renderer(), sandbox),
                new FeedbackImages(images, out, err), out)
                .judgeBatch(SceneBatch.PUBLIC, run.ran(), List.of());
        long now = System.nanoTime();
        return new Halfway(new Halfway.Compiled(submission, sources, started),
                new Halfway.PublicScenes(judged, probes, run.printed(), run.ran().took()),
                new Halfway.Spent(new Phases(compileNanos, run.ran().took().toNanos(), now - compareStart),
                        now - start));
    }

    /**
     * The second half of a grade {@link #begin} left halfway: runs the hidden scenes in what the
     * public run left of the time limit, judges them, and gives the verdict. {@code work} is the
     * folder the grade began in, or, after {@link Halfway#setAside}, an empty one.
     */
    public Graded finish(Halfway halfway, Path work, PrintWriter out) throws IOException, InterruptedException {
        long start = System.nanoTime();
        Halfway.Compiled code = halfway.code;
        Halfway.PublicScenes scenes = halfway.publicScenes;
        Phases phases = halfway.spent.phases();
        Explainer explainer = new Explainer(grading, code.submission(), start - halfway.spent.elapsedNanos(), out);
        CompileStep.Started started = code.started();
        long compileNanos = 0;
        if (started == null) {
            started = compiler.compile(code.submission(), code.sources(), work);
            compileNanos = started.renderStart() - started.compileStart();
            if (!started.compiled().compiled()) {
                // In fixed words: this compile ran beside hidden runs, whose use of the machine may have decided it.
                return explainer.failed(Category.Outcome.DOES_NOT_COMPILE, COMPILED_ONCE_ONLY,
                        phases.plus(compileNanos, 0, 0));
            }
        }
        SceneRuns.Ran hidden = runs.runHidden(started, work, scenes.took());
        long compareStart = System.nanoTime();
        List<Judged> judged = new ArrayList<>(scenes.judged());
        judged.addAll(new SceneJudge(grading, scenes.probes(), null, new FeedbackImages(null, out, out), out)
                .judgeBatch(SceneBatch.HIDDEN, hidden, scenes.judged()));
        explainer.lastLinesPrinted(judged, scenes.printed());
        return explainer.verdict(judged, scenes.probes(), phases.plus(compileNanos, hidden.took().toNanos(),
                System.nanoTime() - compareStart));
    }

    /** What {@link #begin} gave: a whole grade, or one {@link Halfway} done. */
    public sealed interface Begun permits Finished, Halfway {
    }

    /** A grade that ended before any hidden scene could run. */
    public record Finished(Graded graded) implements Begun {
    }

    /**
     * A grade whose public scenes are run and judged, and whose hidden ones are not yet: what
     * {@link #finish} needs, and nothing of the public run's images.
     */
    public record Halfway(Compiled code, PublicScenes publicScenes, Spent spent) implements Begun {
        /**
         * The most bytes of compiled classes a grade set aside keeps on the grader's disk: far more
         * than any solution's, far less than a compile may make.
         */
        static final long KEPT_CLASS_BYTES = 4L << 20;
        /** The most class files a grade set aside keeps, as {@link #KEPT_CLASS_BYTES}. */
        static final int KEPT_CLASS_FILES = 200;

        /**
         * The submission, its checked sources, and their compile: null once {@link #setAside} deleted the
         * classes, which {@link #finish} then compiles again.
         */
        record Compiled(Submission submission, SourceCheck.Sources sources, CompileStep.Started started) {
        }

        /** The public scenes judged, the behaviour comparison's findings, what the code printed, and the run's time. */
        record PublicScenes(List<Judged> judged, BehaviourFindings probes, String printed, Duration took) {
            PublicScenes {
                judged = List.copyOf(judged);
            }
        }

        /** The grade's time so far: by phase, and in all. */
        record Spent(Phases phases, long elapsedNanos) {
        }

        /**
         * This grade as it waits for its hidden scenes: with the public run's folder deleted from
         * {@code work}, and, when the classes are more than a solution's, {@code work} emptied, so
         * that {@link #finish} compiles them again. What waits on the grader's disk is then small
         * whatever the code made.
         */
        public Halfway setAside(Path work) throws IOException {
            deleted(work.resolve(SceneRuns.PUBLIC_RUN));
            if (small(code.started().classes())) {
                return this;
            }
            try (var entries = Files.list(work)) {
                for (Path entry : entries.toList()) {
                    deleted(entry);
                }
            }
            return new Halfway(new Compiled(code.submission(), code.sources(), null), publicScenes, spent);
        }

        private static void deleted(Path folder) throws IOException {
            String failed = WorkFolder.delete(folder);
            if (failed != null) {
                throw new IOException(failed);
            }
        }

        /** Whether {@code classes} holds at most the kept bytes and files, by a walk that follows no link. */
        private static boolean small(Path classes) throws IOException {
            long[] bytesAndFiles = new long[2];
            Files.walkFileTree(classes, new SimpleFileVisitor<>() {
                @Override
                public FileVisitResult visitFile(Path file, BasicFileAttributes attributes) {
                    bytesAndFiles[0] += attributes.size();
                    return ++bytesAndFiles[1] > KEPT_CLASS_FILES || bytesAndFiles[0] > KEPT_CLASS_BYTES
                            ? FileVisitResult.TERMINATE : FileVisitResult.CONTINUE;
                }
            });
            return bytesAndFiles[1] <= KEPT_CLASS_FILES && bytesAndFiles[0] <= KEPT_CLASS_BYTES;
        }
    }

    public static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }
}
