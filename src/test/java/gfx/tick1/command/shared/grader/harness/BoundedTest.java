package gfx.tick1.command.shared.grader.harness;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;

/**
 * Bounded calls of the student's code: "no answer" means the code worked past its limit, or waited past its limit
 * and the run's spare time, not that the machine was slow.
 */
class BoundedTest {

    private static final long LIMIT_MILLIS = 100;
    /** Spare time enough for every call below that waits and then returns. */
    private static final long SPARE_MILLIS = 5_000;

    @Test
    void aCallThatWaitsLongerThanItsLimitWithoutWorkingStillGivesItsAnswer() {
        // As a correct call does on a busy machine: it waits for a core longer than it works.
        Bounded.Outcome<String> outcome = new Bounded(SPARE_MILLIS).call(() -> {
            Thread.sleep(3 * LIMIT_MILLIS);
            return "answer";
        }, LIMIT_MILLIS);

        assertThat(outcome).as("a call that waited three times its limit and then returned")
                .isEqualTo(new Bounded.Outcome<>(Bounded.Ending.RETURNED, "answer"));
    }

    /**
     * Each call sleeps as long as its limit, so that it returns about when the clock passes the limit. The limit is
     * 10 ms, not less: a new thread's own start (its stack's and first allocation's pages) can cost it a millisecond
     * of processor time on a loaded machine, and a call that has worked its limit is rightly stopped.
     */
    @Test
    void everyCallThatReturnsAsItsLimitPassesGivesItsAnswer() {
        Bounded bounded = new Bounded(SPARE_MILLIS);
        List<Bounded.Ending> endings = new ArrayList<>();
        for (int call = 0; call < 300; call++) {
            endings.add(bounded.call(() -> {
                Thread.sleep(RACE_MILLIS);
                return "answer";
            }, RACE_MILLIS).ending());
        }

        assertThat(endings).as("300 calls that each return about when their limit passes")
                .containsOnly(Bounded.Ending.RETURNED);
    }

    /** The limit of the calls that return as it passes. */
    private static final long RACE_MILLIS = 10;

    @Test
    void aCallThatWorksPastItsLimitHasNoAnswer() {
        AtomicBoolean over = new AtomicBoolean();
        Bounded.Outcome<String> outcome = new Bounded(SPARE_MILLIS).call(() -> {
            long spins = 0;
            while (!over.get()) {
                spins++;
            }
            return "after " + spins;
        }, LIMIT_MILLIS);
        over.set(true);   // the harness leaves such a thread running; the tests' JVM has other work

        assertThat(outcome.ending()).as("a call that loops").isEqualTo(Bounded.Ending.TIMED_OUT);
    }

    @Test
    void aCallThatWaitsLongerThanTheRunsSpareTimeHasNoAnswer() {
        Bounded.Outcome<String> outcome = new Bounded(2 * LIMIT_MILLIS).call(() -> {
            Thread.sleep(10 * LIMIT_MILLIS);
            return "too late";
        }, LIMIT_MILLIS);

        assertThat(outcome.ending()).as("a call that waited past its limit and all the spare time")
                .isEqualTo(Bounded.Ending.TIMED_OUT);
    }

    @Test
    void afterACallIsStoppedTheRunsLaterCallsHaveNoSpareTime() {
        Bounded bounded = new Bounded(5 * LIMIT_MILLIS);
        CountDownLatch over = new CountDownLatch(1);
        Bounded.Outcome<String> stopped = bounded.call(() -> {
            over.await();
            return "after the test";
        }, LIMIT_MILLIS);
        over.countDown();
        Bounded.Outcome<String> later = bounded.call(() -> {
            Thread.sleep(3 * LIMIT_MILLIS);
            return "answer";
        }, LIMIT_MILLIS);

        assertThat(stopped.ending()).as("a call that waits without end").isEqualTo(Bounded.Ending.TIMED_OUT);
        assertThat(later.ending()).as("a later call that waits three times its limit")
                .isEqualTo(Bounded.Ending.TIMED_OUT);
    }

    @Test
    void aCallMadeWhileTheHarnessThreadIsInterruptedStillGivesItsAnswer() {
        // As after a Renderer.render that left its thread's interrupt flag set: the harness calls on that thread.
        Thread.currentThread().interrupt();
        Bounded.Outcome<String> outcome = callThenClearTheFlag(() -> {
            Thread.sleep(LIMIT_MILLIS / 2);
            return "answer";
        });

        assertThat(outcome).as("a call that returned within its limit, made with the harness's thread interrupted")
                .isEqualTo(new Bounded.Outcome<>(Bounded.Ending.RETURNED, "answer"));
    }

    @Test
    void aCallThatInterruptsTheHarnessThreadStillGivesItsAnswer() {
        Thread harness = Thread.currentThread();
        Bounded.Outcome<String> outcome = callThenClearTheFlag(() -> {
            harness.interrupt();
            Thread.sleep(LIMIT_MILLIS / 2);
            return "answer";
        });

        assertThat(outcome).as("a call that interrupted the harness's thread and returned within its limit")
                .isEqualTo(new Bounded.Outcome<>(Bounded.Ending.RETURNED, "answer"));
    }

    /** {@code work} called within the limit, the test thread's interrupt flag then cleared for the tests after it. */
    private static Bounded.Outcome<String> callThenClearTheFlag(java.util.concurrent.Callable<String> work) {
        try {
            return new Bounded(SPARE_MILLIS).call(work, LIMIT_MILLIS);
        } finally {
            Thread.interrupted();
        }
    }

    @Test
    void aCallThatThrowsIsToldAsThrowing() {
        Bounded.Outcome<String> outcome = new Bounded(SPARE_MILLIS).call(() -> {
            throw new IllegalStateException("the student's exception");
        }, LIMIT_MILLIS);

        assertThat(outcome.ending()).as("a call that threw").isEqualTo(Bounded.Ending.THREW);
    }

    @Test
    void aCallWhoseThreadCannotStartIsToldAsHavingNoThreadAndTheCodeIsNotCalled() {
        AtomicBoolean called = new AtomicBoolean();
        // What Thread.start throws once the run's threads are at the limit of processes and threads.
        Bounded atTheLimit = new Bounded(SPARE_MILLIS, work -> new Thread(work) {
            @Override
            public synchronized void start() {
                throw new OutOfMemoryError("unable to create native thread: possibly out of memory or process/resource "
                        + "limits reached");
            }
        });

        Bounded.Outcome<String> outcome = atTheLimit.call(() -> {
            called.set(true);
            return "answer";
        }, LIMIT_MILLIS);

        assertThat(outcome).as("a call whose thread could not be started")
                .isEqualTo(new Bounded.Outcome<>(Bounded.Ending.NO_THREAD, null));
        assertThat(called).as("whether the code was called").isFalse();
    }
}
