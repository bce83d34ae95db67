package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.core.LauncherConfig;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;

/**
 * The test run's progress lines on Gradle 4.4.1: a test whose assumption does not hold (which the JUnit Platform calls
 * aborted) is counted as skipped and named at the end with the assumption's words.
 */
class TestClassProgressTest {

    /** Two tests run by the test below; in any other run both pass, so that no run of the suite skips them. */
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

    @Test
    void aTestWhoseAssumptionFailsIsCountedAsSkippedAndListedWithItsReason() {
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        Launcher launcher = LauncherFactory.create(LauncherConfig.builder()
                .enableTestExecutionListenerAutoRegistration(false).build());
        Fixture.figuresMissing = true;
        try {
            launcher.execute(LauncherDiscoveryRequestBuilder.request().selectors(selectClass(Fixture.class)).build(),
                    new TestClassProgress(new PrintStream(printed, true, StandardCharsets.UTF_8), true));
        } finally {
            Fixture.figuresMissing = false;
        }
        String lines = printed.toString(StandardCharsets.UTF_8);

        assertThat(lines).as("the run's last lines").containsPattern("2 tests in \\d+ s: 1 passed, 0 failed, 1 skipped")
                .contains("Skipped, and why:\n  TestClassProgressTest$Fixture comparesWithAFigure(): the course's "
                        + "figures are not here")
                .doesNotContainIgnoringCase("aborted");
    }
}
