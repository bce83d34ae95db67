package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.grading.Grading.CourseScene;
import gfx.tick1.command.shared.grader.sandbox.NoImage;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The grade's run step: the public scenes (with the probes), then the hidden ones in a JVM of
 * their own, so that what the student's code prints while it has a hidden scene open is never
 * shown. All within the one time limit.
 */
final class SceneRuns {

    /**
     * Every scene's outcome and traced samples in grading order, what the behaviour comparison
     * found (judged while the hidden scenes render), and what the code printed.
     */
    record Rendered(List<Outcome> outcomes, List<String> traces, CompletableFuture<ProbeFindings> probes,
            String publicPrinted) {
    }

    private final Grading grading;
    private final Sandbox sandbox;
    private final StudentProcess process;
    private final Path scenes;

    SceneRuns(Grading grading, Sandbox sandbox, StudentProcess process, Path scenes) {
        this.grading = grading;
        this.sandbox = sandbox;
        this.process = process;
        this.scenes = scenes;
    }

    Rendered run(CompileStep.Started started, Path work) throws IOException, InterruptedException {
        Grading.Limits limits = grading.limits();
        long deadline = started.renderStart() + limits.timeLimit().toNanos();
        List<Outcome> outcomes = new ArrayList<>();
        List<String> traces = new ArrayList<>();
        CompletableFuture<ProbeFindings> probes = null;
        String publicPrinted = "";
        for (boolean hidden : new boolean[] {false, true}) {
            List<CourseScene> batch = grading.batch(hidden);
            if (batch.isEmpty()) {
                continue;
            }
            Duration left = Duration.ofNanos(deadline - System.nanoTime());
            if (left.toMillis() < 1) {
                batch.forEach(scene -> outcomes.add(new Outcome.Failed(NoImage.TIME_LIMIT,
                        "not rendered: the time limit was used up by the earlier scenes")));
                batch.forEach(scene -> traces.add(null));
                continue;
            }
            StudentProcess.Result result = process.render(started.classes(), new StudentProcess.Batch(
                    Grading.batchScenes(scenes, hidden), sceneFiles(batch.size()), limits.width(), limits.height(),
                    !hidden, hidden), CompileStep.childFolder(sandbox, work, (hidden ? "hidden" : "public") + "-run"),
                    left, limits.timeLimit());
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

    /** The names the scenes of a batch have inside the sandbox: 0.xml, 1.xml, ... */
    private static List<String> sceneFiles(int count) {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            names.add(i + ".xml");
        }
        return names;
    }
}
