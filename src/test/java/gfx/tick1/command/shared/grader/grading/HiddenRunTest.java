package gfx.tick1.command.shared.grader.grading;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;

/**
 * The order of a grade's hidden run: a run whose answers a report quotes never runs beside a hidden scene, where
 * two of the code's JVMs could talk through the cores they share.
 */
class HiddenRunTest {

    private static final SceneRuns.Ran NOTHING = new SceneRuns.Ran(List.of(), List.of(), null);

    @Test
    void aHiddenRunStartedAheadHasEndedWhenAwaitEndReturns() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        AtomicBoolean ended = new AtomicBoolean();
        HiddenRun hidden = HiddenRun.ahead();
        hidden.publicEnded(() -> {
            release.await();
            ended.set(true);
            return NOTHING;
        });
        Thread releaser = new Thread(() -> {
            try {
                Thread.sleep(300);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            release.countDown();
        });
        releaser.start();

        hidden.awaitEnd();

        assertThat(ended).as("the hidden run, once awaitEnd has returned").isTrue();
        releaser.join();
    }

    @Test
    void aHiddenRunAfterJudgingRunsOnlyWhenItsResultIsAsked() throws Exception {
        AtomicBoolean ran = new AtomicBoolean();
        HiddenRun hidden = HiddenRun.afterJudging();
        hidden.publicEnded(() -> {
            ran.set(true);
            return NOTHING;
        });
        hidden.awaitEnd();
        assertThat(ran).as("the hidden run, before its result is asked for").isFalse();

        assertThat(hidden.ran()).as("its result").isSameAs(NOTHING);
        assertThat(ran).as("the hidden run, once its result is asked for").isTrue();
    }
}
