package gfx.tick1.command.preview;

import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * Gives every request a deadline to arrive. The JDK's server reads a request's headers on one of
 * the executor's threads, and the handler reads its body on the same thread, so a client that
 * stops sending in the middle holds that thread; a few such clients would hold them all. This
 * executor interrupts a thread still reading its request when the deadline passes: the
 * connection's channel, which is interruptible, is then closed and the thread freed. A handler
 * calls {@link #requestRead()} once it has the whole request; from then on (a render may take a
 * while) the thread is left alone.
 */
final class RequestDeadline implements Executor {

    private static final ThreadLocal<ScheduledFuture<?>> ALARM = new ThreadLocal<>();
    /** How long a request taken up after its deadline has to be read. */
    private static final long LATE_GRACE_MILLIS = 1000;

    private final ExecutorService threads;
    private final ScheduledExecutorService timer;
    private final long deadlineMillis;

    RequestDeadline(int threadCount, long deadlineMillis) {
        this.threads = Executors.newFixedThreadPool(threadCount, task -> daemon(task, "tick1-preview"));
        this.timer = Executors.newSingleThreadScheduledExecutor(task -> daemon(task, "tick1-preview-deadline"));
        this.deadlineMillis = deadlineMillis;
    }

    @Override
    public void execute(Runnable exchange) {
        // The deadline runs from the request's arrival, not from when a thread takes it up: else
        // stalled connections waiting in the queue would each hold a thread for a whole deadline
        // in turn, and a page request behind N of them would wait N / threads deadlines.
        long arrived = System.nanoTime();
        threads.execute(() -> {
            Thread thread = Thread.currentThread();
            long waited = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - arrived);
            // A request that waited past its deadline has had all that time to arrive: its headers
            // and a small body are in the connection's buffer, and a second is enough to read
            // them. (A large upload taken up that late may be cut off; the page then says so.)
            long left = Math.max(LATE_GRACE_MILLIS, deadlineMillis - waited);
            ScheduledFuture<?> alarm = timer.schedule(thread::interrupt, left, TimeUnit.MILLISECONDS);
            ALARM.set(alarm);
            try {
                exchange.run();
            } finally {
                alarm.cancel(false);
                ALARM.remove();
                Thread.interrupted();   // an alarm that went off just now must not reach the next request
            }
        });
    }

    /** Called by a handler on its thread when the whole request has been read: no deadline any more. */
    static void requestRead() {
        ScheduledFuture<?> alarm = ALARM.get();
        if (alarm != null) {
            alarm.cancel(false);
        }
    }

    void shutdownNow() {
        threads.shutdownNow();
        timer.shutdownNow();
    }

    private static Thread daemon(Runnable task, String name) {
        Thread thread = new Thread(task, name);
        thread.setDaemon(true);
        return thread;
    }
}
