package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Whole runs of tick1 in fresh processes, as the tests start them: by {@code java -cp} with the tests' class path,
 * there being no installed launcher beside the classes.
 */
class ProcessRunsTest {

    @Test
    void aYardstickThatCannotBeBuiltLeavesTick1TimedAloneWithItsOwnArguments() throws IOException {
        ProcessRuns.Beside beside = new ProcessRuns(false).beside(1, List.of("--version"), () -> {
            throw new IOException("no C compiler (cc, gcc or clang) on the path");
        });

        assertThat(beside.tick1()).as("tick1's runs, timed alone").isNotNull();
        assertThat(beside.yardstick()).as("the yardstick's runs").isNull();
        assertThat(beside.missing()).as("why the yardstick was not run").contains("no C compiler");
    }

    @Test
    void aRunThatFailsIsOneShortLineWithoutTheClassPath() {
        IOException failure = catchThrowableOfType(IOException.class,
                () -> new ProcessRuns(false).tick1(1, "--no-such-option"));

        assertThat(failure).as("a run that exits non-zero").isNotNull();
        assertThat(failure.getMessage()).as("the failure")
                .contains("--no-such-option", "exited with 2")
                .doesNotContain(System.getProperty("java.class.path"), "\n");
        assertThat(failure.getMessage().length()).as("the failure's length").isLessThan(400);
    }
}
