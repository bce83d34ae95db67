package gfx.tick1.engine.math;

import static org.assertj.core.api.Assertions.assertThat;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Random;
import org.junit.jupiter.api.Test;

class DoubleDoubleTest {

    private static final MathContext CONTEXT = new MathContext(60);
    private final Random random = new Random(3);

    private static BigDecimal exact(DoubleDouble value) {
        return new BigDecimal(value.hi).add(new BigDecimal(value.lo));
    }

    /** A double over a wide range of magnitudes, either sign. */
    private double anyDouble() {
        return (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(33) - 16);
    }

    private static void assertRelativeError(BigDecimal actual, BigDecimal expected, double bound, String what) {
        BigDecimal error = actual.subtract(expected).abs();
        assertThat(error.compareTo(expected.abs().multiply(new BigDecimal(bound))) <= 0)
                .as("%s: got %s, expected %s", what, actual, expected).isTrue();
    }

    @Test
    void twoSumAndTwoProductAreExact() {
        for (int i = 0; i < 10_000; i++) {
            double a = anyDouble(), b = anyDouble();
            assertThat(exact(DoubleDouble.twoSum(a, b))).as("%s + %s", a, b)
                    .isEqualByComparingTo(new BigDecimal(a).add(new BigDecimal(b)));
            assertThat(exact(DoubleDouble.twoProduct(a, b))).as("%s * %s", a, b)
                    .isEqualByComparingTo(new BigDecimal(a).multiply(new BigDecimal(b)));
        }
    }

    @Test
    void arithmeticIsAccurateToAbout2ToTheMinus104() {
        for (int i = 0; i < 10_000; i++) {
            DoubleDouble x = DoubleDouble.twoProduct(anyDouble(), anyDouble());
            DoubleDouble y = DoubleDouble.twoProduct(anyDouble(), anyDouble());
            BigDecimal bx = exact(x), by = exact(y);
            assertRelativeError(exact(x.multiply(y)), bx.multiply(by), 0x1p-102, "product");
            assertRelativeError(exact(x.divide(y)), bx.divide(by, CONTEXT), 0x1p-102, "quotient");
            assertRelativeError(exact(x.abs().sqrt()), bx.abs().sqrt(CONTEXT), 0x1p-102, "square root");
            // A sum is accurate relative to its terms, not to itself (it may cancel).
            BigDecimal sumError = exact(x.add(y)).subtract(bx.add(by)).abs();
            assertThat(sumError.compareTo(bx.abs().add(by.abs()).multiply(new BigDecimal(0x1p-104))) <= 0)
                    .as("%s + %s", x, y).isTrue();
        }
    }

    @Test
    void floorLooksAtTheLowPartWhenTheHighPartIsAnInteger() {
        assertThat(DoubleDouble.twoSum(64, -1e-20).floor()).isEqualTo(63);
        assertThat(DoubleDouble.twoSum(64, 1e-20).floor()).isEqualTo(64);
        assertThat(DoubleDouble.of(63.5).floor()).isEqualTo(63);
    }

    @Test
    void comparisonSeesTheLowPart() {
        assertThat(DoubleDouble.twoSum(1, 1e-30).compareTo(DoubleDouble.ONE)).isPositive();
        assertThat(DoubleDouble.twoSum(1, -1e-30).signum()).isPositive();
        assertThat(DoubleDouble.twoSum(0, -1e-300).signum()).isNegative();
    }
}
