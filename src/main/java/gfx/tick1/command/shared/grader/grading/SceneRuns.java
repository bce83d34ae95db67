package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.behaviour.BehaviourFindings;
import gfx.tick1.command.shared.grader.grading.Grading.CourseScene;
import gfx.tick1.command.shared.grader.sandbox.NoImage;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.SceneBatch;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The grade's run steps: the public scenes (with the probes), then the hidden ones in a JVM of
 * their own, so that what the student's code prints while it has a hidden scene open is never
 * shown. Both share the one time limit, which the public run's time counts against. The runs render
 * {@code grading}'s scenes, copied into {@code scenes}, with {@code process} in {@code sandbox}.
 */
record SceneRuns(Grading grading, Sandbox sandbox, StudentProcess process, Path scenes) {

    /** One run's outcomes and traced samples, in grading order, and how long it took. */
    record Ran(List<Outcome> outcomes, List<String> traces, Duration took) {
    }

    /**
     * The public run: what {@link Ran} holds, what the behaviour comparison found (judged in the
     * grader while the run's images are read), and the last of what the code printed.
     */
    record PublicRun(Ran ran, CompletableFuture<BehaviourFindings> probes, String printed) {
    }

    /** The public run's output folder in a grade's work folder. */
    private static final String PUBLIC_RUN = "public-run";

    /** Runs the public scenes and the probes, within the whole time limit, which starts as compiling ends. */
    PublicRun runPublic(CompileStep.Started started, Path work) throws IOException, InterruptedException {
        StudentProcess.Result result = run(SceneBatch.PUBLIC, started, work, grading.limits().timeLimit());
        if (result == null) {
            return new PublicRun(new Ran(List.of(), List.of(), Duration.ZERO),
                    CompletableFuture.completedFuture(BehaviourFindings.of(null)), "");
        }
        String log = result.probes();
        return new PublicRun(ran(result, started), CompletableFuture.supplyAsync(() -> BehaviourFindings.of(log)),
                result.outputTail());
    }

    /** Runs the hidden scenes in what the public run, which took {@code used}, left of the time limit. */
    Ran runHidden(CompileStep.Started started, Path work, Duration used) throws IOException, InterruptedException {
        long start = System.nanoTime();
        Duration left = grading.limits().timeLimit().minus(used);
        List<CourseScene> batch = grading.batch(SceneBatch.HIDDEN);
        if (batch.isEmpty()) {
            return new Ran(List.of(), List.of(), Duration.ZERO);
        }
        if (left.toMillis() < 1) {
            List<Outcome> outcomes = new ArrayList<>();
            List<String> traces = new ArrayList<>();
            batch.forEach(scene -> outcomes.add(new Outcome.Failed(NoImage.TIME_LIMIT,
                    "not rendered: the time limit was used up by the earlier scenes")));
            batch.forEach(scene -> traces.add(null));
            return new Ran(outcomes, traces, Duration.ZERO);
        }
        StudentProcess.Result result = run(SceneBatch.HIDDEN, started, work, left);
        return new Ran(result.outcomes(), result.traces(), Duration.ofNanos(System.nanoTime() - start));
    }

    /** One batch's run in {@code left} of the time limit; null when the batch has no scene. */
    private StudentProcess.Result run(SceneBatch kind, CompileStep.Started started, Path work, Duration left)
            throws IOException, InterruptedException {
        List<CourseScene> batch = grading.batch(kind);
        if (batch.isEmpty()) {
            return null;
        }
        Grading.Limits limits = grading.limits();
        return process.render(started.classes(), new StudentProcess.Batch(Grading.batchScenes(scenes, kind),
                sceneFiles(batch.size()), limits.width(), limits.height(), kind),
                CompileStep.childFolder(sandbox, work, kind == SceneBatch.HIDDEN ? "hidden-run" : PUBLIC_RUN), left,
                limits.timeLimit());
    }

    private static Ran ran(StudentProcess.Result result, CompileStep.Started started) {
        return new Ran(result.outcomes(), result.traces(), Duration.ofNanos(System.nanoTime() - started.renderStart()));
    }

    /** The names the scenes of a batch have inside the sandbox: 0.xml, 1.xml, ... */
    private static List<String> sceneFiles(int count) {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            names.add(i + ".xml");
        }
        return names;
    }
}
