package gfx.tick1.command.shared.grader.grading;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;

/**
 * When a grade runs its hidden scenes: once the public scenes are judged ({@link #afterJudging}), or as soon as the
 * public run has ended ({@link #ahead}), on a thread of its own, so that one student's hidden run and the judging and
 * explaining of the public scenes share the machine's cores instead of waiting for each other. Either way it starts
 * only after the public run has ended, so that no run whose output a report quotes ran beside a hidden scene.
 */
abstract class HiddenRun {

    /** Told that the public run has ended, having taken {@code used} of the time limit. */
    abstract void publicEnded(SceneRuns runs, CompileStep.Started started, Path work, Duration used);

    /** The hidden run's result, run now (in what {@code used} left of the time limit) unless it was started ahead. */
    abstract SceneRuns.Ran ran(SceneRuns runs, CompileStep.Started started, Path work, Duration used)
            throws IOException, InterruptedException;

    /** Stops a run started ahead whose result was never asked for (the grade failed before it). */
    void abandon() {
    }

    /** The hidden run after the public scenes are judged: one JVM of the code's at a time beside this one. */
    static HiddenRun afterJudging() {
        return new HiddenRun() {
            @Override
            void publicEnded(SceneRuns runs, CompileStep.Started started, Path work, Duration used) {
            }

            @Override
            SceneRuns.Ran ran(SceneRuns runs, CompileStep.Started started, Path work, Duration used)
                    throws IOException, InterruptedException {
                return runs.runHidden(started, work, used);
            }
        };
    }

    /** The hidden run started as soon as the public run has ended. */
    static HiddenRun ahead() {
        return new HiddenRun() {
            private FutureTask<SceneRuns.Ran> task;

            @Override
            void publicEnded(SceneRuns runs, CompileStep.Started started, Path work, Duration used) {
                task = new FutureTask<>(() -> runs.runHidden(started, work, used));
                Thread thread = new Thread(task, "tick1-hidden-run");
                thread.setDaemon(true);
                thread.start();
            }

            @Override
            SceneRuns.Ran ran(SceneRuns runs, CompileStep.Started started, Path work, Duration used)
                    throws IOException, InterruptedException {
                if (task == null) {
                    return runs.runHidden(started, work, used);
                }
                try {
                    return task.get();
                } catch (ExecutionException e) {
                    if (e.getCause() instanceof IOException cause) {
                        throw cause;
                    }
                    if (e.getCause() instanceof InterruptedException cause) {
                        throw cause;
                    }
                    Causes.throwIfUnchecked(e.getCause());
                    throw new IllegalStateException("the hidden run threw a checked exception it does not declare",
                            e.getCause());
                }
            }

            @Override
            void abandon() {
                if (task != null) {
                    task.cancel(true);
                }
            }
        };
    }
}
