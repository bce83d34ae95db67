package gfx.tick1.command.shared.grader.harness;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Runs pieces of the student's code, each in a thread of its own for at most a given time, so
 * that one call that loops or throws fails alone and the harness goes on. A thread that does not
 * return is left running (Java cannot stop it); the harness halts the JVM when it is done.
 *
 * <p>On a busy machine a correct call can wait for a core longer than it works, and "no answer"
 * must mean that the code did not return, not that the machine was slow. So a call past its limit
 * by the clock that has not yet had that much processor time goes on, drawing on spare clock time
 * that all the calls of a run share: a run's calls together can outlast their limits by no more
 * than that, whatever the code does (waits, sleeps, or leaves work to threads of its own). Once a
 * call is stopped, the run has no spare time left: its threads still run beside the later calls,
 * which then get the clock's limit alone, as a call that waits on such threads would never have
 * the processor time. The thread's processor time is read only once the clock has passed the limit,
 * so a call that returns in time costs nothing more.
 */
final class Bounded {

    /** The spare clock time of one run of the harness: well inside the shortest time limit of a run. */
    static final long RUN_SPARE_MILLIS = 5_000;
    /** The calls of this JVM's run. */
    static final Bounded RUN = new Bounded(RUN_SPARE_MILLIS);
    /** How often a call past its limit by the clock has its processor time read again. */
    private static final long POLL_MILLIS = 20;

    /**
     * How a bounded call ended: NO_THREAD when its thread could not be started, so the code was not called (the
     * run's threads, the code's own left running among them, are at the limit of processes and threads).
     */
    enum Ending { RETURNED, THREW, TIMED_OUT, NO_THREAD }

    /** The ending, and the value when it returned. */
    record Outcome<T>(Ending ending, T value) {
    }

    /** The spare clock time left to the calls, in nanoseconds. */
    private long spareNanos;
    /** Makes each call's thread. */
    private final ThreadFactory threads;

    /** Calls that share {@code spareMillis} of clock time beyond their limits. */
    Bounded(long spareMillis) {
        this(spareMillis, work -> new Thread(work, "probe"));
    }

    /** Calls that share {@code spareMillis} of clock time beyond their limits, each in a thread of {@code threads}. */
    Bounded(long spareMillis, ThreadFactory threads) {
        spareNanos = TimeUnit.MILLISECONDS.toNanos(spareMillis);
        this.threads = threads;
    }

    /** Runs {@code work}, for at most {@code millis} of its thread's processor time (see above). */
    synchronized <T> Outcome<T> call(Callable<T> work, long millis) {
        FutureTask<T> task = new FutureTask<>(work);
        Thread thread = threads.newThread(task);
        thread.setDaemon(true);
        try {
            thread.start();
        } catch (OutOfMemoryError noNativeThread) {
            // The harness's own failure, not the code's: the call's ending says it, and the harness goes on.
            return new Outcome<>(Ending.NO_THREAD, null);
        }
        long limit = TimeUnit.MILLISECONDS.toNanos(millis);
        try {
            try {
                return new Outcome<>(Ending.RETURNED, answer(task, limit));
            } catch (TimeoutException pastTheClock) {
                while (spareNanos > 0 && !task.isDone() && !working(thread, limit)) {
                    long waited = System.nanoTime();
                    try {
                        return new Outcome<>(Ending.RETURNED, answer(task, TimeUnit.MILLISECONDS.toNanos(POLL_MILLIS)));
                    } catch (TimeoutException stillRunning) {
                        spareNanos -= System.nanoTime() - waited;
                    }
                }
                try {
                    return new Outcome<>(Ending.RETURNED, answer(task, 0));
                } catch (TimeoutException stopped) {
                    spareNanos = 0;
                    return new Outcome<>(Ending.TIMED_OUT, null);
                }
            }
        } catch (ExecutionException e) {
            return new Outcome<>(Ending.THREW, null);
        }
    }

    /**
     * The answer of {@code task} once it is done, waiting at most {@code nanos} of the clock. Nothing of tick1
     * interrupts the harness's thread, but the student's code can (a render that leaves its thread's interrupt
     * flag set, a call that interrupts every thread): the wait goes on and the flag stays cleared, for a call
     * that answers in time has answered, whatever else the code did.
     */
    private static <T> T answer(FutureTask<T> task, long nanos) throws ExecutionException, TimeoutException {
        long end = System.nanoTime() + nanos;
        while (true) {
            try {
                return task.get(Math.max(0, end - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (InterruptedException byTheStudentsCode) {
                // get has cleared the flag: wait again for what is left, unless the code keeps interrupting
                if (end - System.nanoTime() <= 0 && !task.isDone()) {
                    throw new TimeoutException();
                }
            }
        }
    }

    /**
     * Whether {@code thread} has had at least {@code limit} nanoseconds of processor time: true too where the JVM
     * cannot tell, so that the clock's limit is the limit there.
     */
    private static boolean working(Thread thread, long limit) {
        ThreadMXBean processorTimes = ManagementFactory.getThreadMXBean();
        long used = processorTimes.isThreadCpuTimeSupported() ? processorTimes.getThreadCpuTime(thread.getId()) : -1;
        return used < 0 || used >= limit;
    }
}
