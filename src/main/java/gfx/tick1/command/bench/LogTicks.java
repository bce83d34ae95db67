package gfx.tick1.command.bench;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Which ticks of a logarithmic axis from {@code min} to {@code max} carry a label. The axis has a
 * tick at every whole multiple of each power of ten (1, 2, ... 9, 10, 20, ...); labelled are the
 * 1-2-5 steps (1, 2, 5, 10, 20, 50, ...); where the range is too narrow for three of those, the
 * 1-2-3-5 steps, or else every tick; where it spans more than three powers of ten, only the powers,
 * so that the labels do not crowd.
 */
record LogTicks(double min, double max) {

    private static final double[] ONE_TWO_FIVE = {1, 2, 5};
    private static final double[] ONE_TWO_THREE_FIVE = {1, 2, 3, 5};
    private static final double[] EVERY = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    private static final double[] DECADES = {1};

    LogTicks {
        if (!(min > 0 && max > min)) {
            throw new IllegalArgumentException("a logarithmic axis needs 0 < min < max, not " + min + " to " + max);
        }
    }

    /** The labelled values between min and max, smallest first. */
    List<Double> labelled() {
        if (Math.log10(max / min) > 3) {
            return within(DECADES);
        }
        for (double[] mantissas : new double[][] {ONE_TWO_FIVE, ONE_TWO_THREE_FIVE}) {
            List<Double> steps = within(mantissas);
            if (steps.size() >= 3) {
                return steps;
            }
        }
        return within(EVERY);
    }

    /** A tick's number as a reader writes it: 0.5, 20, 1,000. */
    static String text(double value) {
        if (value >= 1) {
            return String.format(Locale.ROOT, "%,d", Math.round(value));
        }
        return new BigDecimal(Double.toString(value)).stripTrailingZeros().toPlainString();
    }

    private List<Double> within(double[] mantissas) {
        List<Double> values = new ArrayList<>();
        for (int exponent = (int) Math.floor(Math.log10(min)); exponent <= (int) Math.ceil(Math.log10(max));
                exponent++) {
            for (double mantissa : mantissas) {
                // As a decimal, so that 0.3 is 0.3 and not 0.30000000000000004.
                double value = new BigDecimal(mantissa).scaleByPowerOfTen(exponent).doubleValue();
                if (value >= min && value <= max) {
                    values.add(value);
                }
            }
        }
        return values;
    }
}
