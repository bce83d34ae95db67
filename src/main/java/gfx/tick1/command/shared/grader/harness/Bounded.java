package gfx.tick1.command.shared.grader.harness;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Runs a piece of the student's code in a thread of its own for at most a given time, so that
 * one call that loops or throws fails alone and the harness goes on. A thread that does not
 * return is left running (Java cannot stop it); the harness halts the JVM when it is done.
 *
 * <p>The time is the thread's processor time, not the clock's: on a busy machine a correct call
 * can wait for a core longer than it works, and "no answer" must mean the code itself did not
 * return. Code that waits without working (a sleep, a lock) is stopped by the clock instead,
 * {@link #CLOCK_SLACK_MILLIS} after the limit. The thread's processor time is read only once the
 * clock has passed the limit, so a call that returns in time costs nothing more.
 */
final class Bounded {

    /** How much longer than the limit a call may take by the clock, working or not. */
    static final long CLOCK_SLACK_MILLIS = 10_000;
    /** How often a call past its limit by the clock has its processor time read again. */
    private static final long POLL_MILLIS = 20;

    /** How a bounded call ended. */
    enum Ending { RETURNED, THREW, TIMED_OUT }

    /** The ending, and the value when it returned. */
    record Outcome<T>(Ending ending, T value) {
    }

    private Bounded() {
    }

    static <T> Outcome<T> call(Callable<T> work, long millis) {
        return call(work, millis, millis + CLOCK_SLACK_MILLIS);
    }

    /** As {@link #call(Callable, long)}, stopping code that waits without working at {@code clockMillis}. */
    static <T> Outcome<T> call(Callable<T> work, long millis, long clockMillis) {
        FutureTask<T> task = new FutureTask<>(work);
        Thread thread = new Thread(task, "probe");
        thread.setDaemon(true);
        long start = System.nanoTime();
        thread.start();
        long limit = TimeUnit.MILLISECONDS.toNanos(millis), clockLimit = TimeUnit.MILLISECONDS.toNanos(clockMillis);
        try {
            try {
                return new Outcome<>(Ending.RETURNED, task.get(millis, TimeUnit.MILLISECONDS));
            } catch (TimeoutException e) {
                while (!working(thread, limit) && System.nanoTime() - start < clockLimit) {
                    try {
                        return new Outcome<>(Ending.RETURNED, task.get(POLL_MILLIS, TimeUnit.MILLISECONDS));
                    } catch (TimeoutException stillRunning) {
                        // read its processor time again
                    }
                }
                return new Outcome<>(Ending.TIMED_OUT, null);
            }
        } catch (ExecutionException e) {
            return new Outcome<>(Ending.THREW, null);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new Outcome<>(Ending.TIMED_OUT, null);
        }
    }

    /**
     * Whether {@code thread} has had at least {@code limit} nanoseconds of processor time: true too where the JVM
     * cannot tell, so that the clock's limit is the limit there, as it always was.
     */
    private static boolean working(Thread thread, long limit) {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        long used = threads.isThreadCpuTimeSupported() ? threads.getThreadCpuTime(thread.getId()) : -1;
        return used < 0 || used >= limit;
    }
}
