package gfx.tick1.command.grade;

import gfx.tick1.command.shared.cli.OutputGate;
import gfx.tick1.engine.io.OnExit;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;

/**
 * A grade's stop (Ctrl-C, SIGTERM), from the moment SIGTERM is tick1's to handle: one shutdown hook, whose action
 * the grade replaces as it gets further (what to stop and delete as well as saying so). Java runs its shutdown
 * hooks all at once and ends when they have: one hook, so that one line is said, last. The grade's own end and the
 * stop exclude each other, whichever comes first holds, and each waits for the other's clean-up to finish.
 */
final class GradeStop {

    private enum Ending { RUNNING, ENDED, STOPPED }

    private final AtomicReference<Ending> ending = new AtomicReference<>(Ending.RUNNING);
    /** Counted down once the clean-up of the end or of the stop is done. */
    private final CountDownLatch done = new CountDownLatch(1);
    private final Thread hook = new Thread(this::stop, "tick1-grade-stop");
    private final OutputGate gate;
    private volatile Runnable action;

    private GradeStop(OutputGate gate, Runnable action) {
        this.gate = gate;
        this.action = action;
    }

    /** From now on, a stop shuts {@code gate} saying {@code line}. */
    static GradeStop saying(OutputGate gate, String line) {
        GradeStop stop = new GradeStop(gate, () -> gate.shutSaying(line));
        Runtime.getRuntime().addShutdownHook(stop.hook);
        return stop;
    }

    /** The grade's outputs, which the stop shuts as it says its line. */
    OutputGate gate() {
        return gate;
    }

    /** From now on, a stop does {@code stopping} instead: it says the stop's line and undoes what the grade began. */
    void onStop(Runnable stopping) {
        action = stopping;
    }

    /**
     * The grade's end (in a {@code finally}): runs {@code cleanUp}, unless a stop came first, whose action cleans up
     * instead; then this waits for the stop to finish. A grade ended by the stop itself (its student's process
     * killed, a write refused) ends while the JVM is stopping: that is the stop's. Only the first end counts.
     */
    void end(Runnable cleanUp) {
        if (!OnExit.stopping() && ending.compareAndSet(Ending.RUNNING, Ending.ENDED)) {
            try {
                cleanUp.run();
            } finally {
                done.countDown();
                try {
                    Runtime.getRuntime().removeShutdownHook(hook);
                } catch (IllegalStateException e) {
                    // A stop after the end: the hook waits for nothing and does nothing.
                }
            }
        } else {
            awaitDone();
        }
    }

    private void stop() {
        if (ending.compareAndSet(Ending.RUNNING, Ending.STOPPED)) {
            try {
                action.run();
            } finally {
                done.countDown();
            }
        } else {
            awaitDone();
        }
    }

    private void awaitDone() {
        try {
            done.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
