package gfx.tick1.command.shared.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import org.junit.jupiter.api.Test;

/** A command's exit-status help, from the constants that hold the statuses. */
class ExitStatusesTest {

    static final class Counter {
        @ExitStatus("counted")
        static final int EXIT_COUNTED = 0;
        @ExitStatus("the count could not be made, or the command line is wrong")
        static final int EXIT_CANNOT_COUNT = 2;
        static final int UNDOCUMENTED = 7;
    }

    static final class Twice {
        @ExitStatus("one meaning")
        static final int EXIT_ONE = 1;
        @ExitStatus("another meaning")
        static final int EXIT_ALSO_ONE = 1;
    }

    @Test
    void aCommandsOwnWordsComeFirstAndTheSharedStatusesFillTheGaps() {
        Map<Integer, String> statuses = ExitStatuses.of(Counter.class);
        assertThat(statuses.keySet()).containsExactly(0, 2, ExitStatuses.EXIT_INTERNAL);
        assertThat(statuses.get(2)).isEqualTo("the count could not be made, or the command line is wrong");
        assertThat(statuses.get(ExitStatuses.EXIT_INTERNAL)).startsWith("an internal error");
    }

    @Test
    void aClassWithNoStatusesHasNoExitStatusHelp() {
        assertThat(ExitStatuses.of(String.class)).isEmpty();
    }

    @Test
    void aStatusGivenTwoMeaningsIsRefused() {
        assertThatThrownBy(() -> ExitStatuses.of(Twice.class)).hasMessageContaining("a second meaning for status 1");
    }
}
