package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.behaviour.Behaviour;
import gfx.tick1.command.shared.behaviour.BehaviourFindings;
import gfx.tick1.command.shared.behaviour.PixelCounterexample;
import gfx.tick1.command.shared.grader.grading.SceneJudge.Judged;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.SceneBatch;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
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

    /**
     * One submission's grade: the result, whether its images could not be written, how its
     * two methods behaved on the behaviour inputs (not run: {@link Behaviour#ran} false), and the compiler's errors
     * when the code did not compile (else empty).
     */
    public record Graded(StudentResult result, boolean imagesUnwritable, Behaviour behaviour,
            List<String> compileErrors) {

        Graded(StudentResult result, boolean imagesUnwritable, Behaviour behaviour) {
            this(result, imagesUnwritable, behaviour, List.of());
        }
    }

    /** The course tester's own words for a pass. */
    public static final String CONGRATULATIONS = "Congratulations! Your code passed the tester.";
    /** The words of a matching image that their methods do not give. */
    public static final String NOT_FROM_THE_CODE = "the image does not come from your Sphere and Renderer";

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
     * Grades {@code submission}: checks and compiles the files, runs the public scenes and the probes,
     * then the hidden scenes in a JVM of their own, judges them, and gives the verdict. {@code work}
     * is an empty folder for this grade (the caller deletes it), {@code images} where the images of
     * failing scenes go; {@code out} gets the tester's report, {@code err} a line when the images
     * cannot be written.
     */
    public Graded grade(Submission submission, Path work, Path images, PrintWriter out, PrintWriter err)
            throws IOException, InterruptedException {
        return grade(submission, work, images, out, err, HiddenRun.afterJudging());
    }

    /**
     * Grades {@code submission} as {@link #grade} does, but starts the hidden scenes' run as soon as the public run
     * has ended, while the public scenes are judged and a wrong image explained here: the grade then waits for the
     * longer of the two rather than for both. The code's JVM and this one's explaining then hold their memory at
     * once, so this is not for a grade that must fit VPL's memory limit.
     */
    public Graded gradeWithHiddenRunAhead(Submission submission, Path work, Path images, PrintWriter out,
            PrintWriter err) throws IOException, InterruptedException {
        return grade(submission, work, images, out, err, HiddenRun.ahead());
    }

    private Graded grade(Submission submission, Path work, Path images, PrintWriter out, PrintWriter err,
            HiddenRun hiddenRun) throws IOException, InterruptedException {
        boolean finished = false;
        try {
            Graded graded = judged(submission, work, new FeedbackImages(images, out, err), out, hiddenRun);
            finished = true;
            return graded;
        } finally {
            if (!finished) {
                hiddenRun.abandon();
            }
        }
    }

    private Graded judged(Submission submission, Path work, FeedbackImages images, PrintWriter out,
            HiddenRun hiddenRun) throws IOException, InterruptedException {
        Explainer explainer = new Explainer(grading, submission, System.nanoTime(), out);
        SourceCheck.Checked checked = SourceCheck.check(submission);
        if (checked instanceof SourceCheck.Problem problem) {
            return explainer.failed(problem.category(), problem.reason());
        }
        SourceCheck.Sources sources = (SourceCheck.Sources) checked;
        CompileStep.Started started = compiler.compile(submission, sources, work);
        if (!started.compiled().compiled()) {
            return explainer.didNotCompile(started.compiled());
        }
        out.println("Compiled " + submission.sphere().path() + " and " + submission.renderer().path()
                + " with the starter code.");
        SceneRuns.PublicRun run = runs.runPublic(started, work);
        hiddenRun.publicEnded(() -> runs.runHidden(started, work, run.ran().took()));
        BehaviourFindings probes = run.probes().join();
        List<Judged> publicScenes = new SceneJudge(grading, probes, new SceneJudge.Code(
                new PixelCounterexample.Code(sources.sphere(), sources.renderer(), sandbox), hiddenRun), images, out)
                .judgeBatch(SceneBatch.PUBLIC, run.ran(), List.of());
        SceneRuns.Ran hidden = hiddenRun.ran();
        List<Judged> judged = new ArrayList<>(publicScenes);
        judged.addAll(new SceneJudge(grading, probes, null, new FeedbackImages(null, out, out), out)
                .judgeBatch(SceneBatch.HIDDEN, hidden, publicScenes));
        explainer.lastLinesPrinted(judged, run.printed());
        return explainer.verdict(judged, probes);
    }
}
