package gfx.tick1.command.shared.grader.harness;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;

/** A bounded call of the student's code: "no answer" means the code worked past its limit, not that it waited. */
class BoundedTest {

    private static final long LIMIT_MILLIS = 100;

    @Test
    void aCallThatWaitsLongerThanItsLimitWithoutWorkingStillGivesItsAnswer() {
        // As a correct call does on a busy machine: it waits for a core longer than it works.
        Bounded.Outcome<String> outcome = Bounded.call(() -> {
            Thread.sleep(3 * LIMIT_MILLIS);
            return "answer";
        }, LIMIT_MILLIS);

        assertThat(outcome).as("a call that waited three times its limit and then returned")
                .isEqualTo(new Bounded.Outcome<>(Bounded.Ending.RETURNED, "answer"));
    }

    @Test
    void aCallThatWorksPastItsLimitHasNoAnswer() {
        AtomicBoolean over = new AtomicBoolean();
        Bounded.Outcome<String> outcome = Bounded.call(() -> {
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
    void aCallThatWaitsWithoutEndHasNoAnswer() {
        CountDownLatch over = new CountDownLatch(1);
        Bounded.Outcome<String> outcome = Bounded.call(() -> {
            over.await();
            return "after the test";
        }, LIMIT_MILLIS, 5 * LIMIT_MILLIS);
        over.countDown();

        assertThat(outcome.ending()).as("a call that waits without end").isEqualTo(Bounded.Ending.TIMED_OUT);
    }

    @Test
    void aCallThatThrowsIsToldAsThrowing() {
        Bounded.Outcome<String> outcome = Bounded.call(() -> {
            throw new IllegalStateException("the student's exception");
        }, LIMIT_MILLIS);

        assertThat(outcome.ending()).as("a call that threw").isEqualTo(Bounded.Ending.THREW);
    }
}
