package gfx.tick1.command.shared.grader.grading;

import java.io.IOException;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;

/**
 * When a grade runs its hidden scenes: once the public scenes are judged ({@link #afterJudging}), or as soon as the
 * public run has ended ({@link #ahead}), on a thread of its own, so that one student's hidden run and the judging of
 * the public scenes share the machine's cores instead of waiting for each other. Either way no run whose answers a
 * report quotes runs beside a hidden scene: the hidden run starts only after the public run has ended, and a run
 * that explains a public scene waits for it to end ({@link #awaitEnd}). Two of the code's JVMs at once could
 * otherwise talk through the cores they share, and a hidden scene's content reach the report.
 */
abstract class HiddenRun {

    /** The hidden scenes' run, once the public run has ended. */
    private Callable<SceneRuns.Ran> run;

    /** Told that the public run has ended: {@code hiddenRun} runs the hidden scenes. */
    void publicEnded(Callable<SceneRuns.Ran> hiddenRun) {
        this.run = hiddenRun;
    }

    /** The hidden run's result: run now, unless it was started ahead. */
    abstract SceneRuns.Ran ran() throws IOException, InterruptedException;

    /** Returns once no hidden scene runs: before the code runs again for answers a report quotes. */
    void awaitEnd() throws InterruptedException {
    }

    /** Stops a run started ahead whose result was never asked for (the grade failed before it). */
    void abandon() {
    }

    /** The hidden run after the public scenes are judged: one JVM of the code's at a time beside this one. */
    static HiddenRun afterJudging() {
        return new HiddenRun() {
            @Override
            SceneRuns.Ran ran() throws IOException, InterruptedException {
                FutureTask<SceneRuns.Ran> now = new FutureTask<>(super.run);
                now.run();
                return result(now);
            }
        };
    }

    /** The hidden run started as soon as the public run has ended. */
    static HiddenRun ahead() {
        return new HiddenRun() {
            private FutureTask<SceneRuns.Ran> task;

            @Override
            void publicEnded(Callable<SceneRuns.Ran> hiddenRun) {
                task = new FutureTask<>(hiddenRun);
                Thread thread = new Thread(task, "tick1-hidden-run");
                thread.setDaemon(true);
                thread.start();
            }

            @Override
            SceneRuns.Ran ran() throws IOException, InterruptedException {
                return result(task);
            }

            @Override
            void awaitEnd() throws InterruptedException {
                try {
                    task.get();
                } catch (ExecutionException | CancellationException e) {
                    // It ended: how is for ran() to say.
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

    /** What {@code task} returned, or what it threw, as thrown by the hidden run itself. */
    private static SceneRuns.Ran result(FutureTask<SceneRuns.Ran> task) throws IOException, InterruptedException {
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
}
