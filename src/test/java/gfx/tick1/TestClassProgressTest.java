package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.parallel.ResourceLock;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.core.LauncherConfig;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;

/**
 * The test run's progress lines on Gradle 4.4.1: a test whose assumption does not hold (which the JUnit Platform calls
 * aborted) is counted as skipped and named at the end with the assumption's words, and the run ends with its slowest
 * classes.
 */
@ResourceLock(TestClassProgressTest.FIXTURE)
class TestClassProgressTest {

    /** What {@link Fixture}'s switch is, as a resource: the suite's own run of Fixture never sees it on. */
    static final String FIXTURE = "gfx.tick1.TestClassProgressTest.Fixture.figuresMissing";

    /** Two tests run by the tests below; in any other run both pass, so that no run of the suite skips them. */
    @ResourceLock(FIXTURE)
    static final class Fixture {
        static volatile boolean figuresMissing;

        @Test
        void comparesWithAFigure() {
            assumeTrue(!figuresMissing, "skipped: the course's figures are not here");
        }

        @Test
        void passes() {
        }
    }

    /** What the listener prints for a run of {@link Fixture}, with its first test skipped or not. */
    private static String progressOfFixture(boolean figuresMissing) {
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        Launcher launcher = LauncherFactory.create(LauncherConfig.builder()
                .enableTestExecutionListenerAutoRegistration(false).build());
        Fixture.figuresMissing = figuresMissing;
        try {
            launcher.execute(LauncherDiscoveryRequestBuilder.request().selectors(selectClass(Fixture.class)).build(),
                    new TestClassProgress(new PrintStream(printed, true, StandardCharsets.UTF_8), true));
        } finally {
            Fixture.figuresMissing = false;
        }
        return printed.toString(StandardCharsets.UTF_8);
    }

    @Test
    void aTestWhoseAssumptionFailsIsCountedAsSkippedAndListedWithItsReason() {
        String lines = progressOfFixture(true);

        assertThat(lines).as("the run's last lines").containsPattern("2 tests in \\d+ s: 1 passed, 0 failed, 1 skipped")
                .contains("Skipped, and why:\n  TestClassProgressTest$Fixture comparesWithAFigure(): the course's "
                        + "figures are not here")
                .doesNotContainIgnoringCase("aborted");
    }

    @Test
    void theRunEndsWithItsSlowestClassesAndTheirTimes() {
        String lines = progressOfFixture(false);

        assertThat(lines).as("the run's last lines")
                .containsPattern("2 tests in \\d+ s: 2 passed, 0 failed, 0 skipped\n"
                        + "Slowest classes:\n +\\d+\\.\\d s  TestClassProgressTest\\$Fixture\n$");
    }
}
