package gfx.tick1.engine.fast;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.stream.IntStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The order in which a frame's rows are handed out: a few spread ones first, then top down, each once. */
class RowsInOrderTest {

    @ParameterizedTest
    @ValueSource(ints = {1, 2, 31, 32, 33, 480, 2160, 16384})
    void everyRowIsTakenExactlyOnce(int height) {
        int[] order = RowsInOrder.order(height);
        assertThat(Arrays.stream(order).sorted().toArray()).isEqualTo(IntStream.range(0, height).toArray());
    }

    @ParameterizedTest
    @ValueSource(ints = {32, 480, 2160})
    void theFirstRowsSpanTheFrameAndTheRestGoTopDown(int height) {
        int[] order = RowsInOrder.order(height);
        assertThat(order[0]).isZero();
        assertThat(order[7]).isEqualTo(height - 1);
        int[] rest = Arrays.copyOfRange(order, 8, height);
        assertThat(rest).isSorted();
    }
}
