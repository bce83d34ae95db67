package gfx.tick1.command.shared.grader.harness;

import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Runs a piece of the student's code in a thread of its own for at most a given time, so that
 * one call that loops or throws fails alone and the harness goes on. A thread that does not
 * return is left running (Java cannot stop it); the harness halts the JVM when it is done.
 */
final class Bounded {

    /** How a bounded call ended. */
    enum Ending { RETURNED, THREW, TIMED_OUT }

    /** The ending, and the value when it returned. */
    record Outcome<T>(Ending ending, T value) {
    }

    private Bounded() {
    }

    static <T> Outcome<T> call(Callable<T> work, long millis) {
        FutureTask<T> task = new FutureTask<>(work);
        Thread thread = new Thread(task, "probe");
        thread.setDaemon(true);
        thread.start();
        try {
            return new Outcome<>(Ending.RETURNED, task.get(millis, TimeUnit.MILLISECONDS));
        } catch (TimeoutException e) {
            return new Outcome<>(Ending.TIMED_OUT, null);
        } catch (ExecutionException e) {
            return new Outcome<>(Ending.THREW, null);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new Outcome<>(Ending.TIMED_OUT, null);
        }
    }
}
