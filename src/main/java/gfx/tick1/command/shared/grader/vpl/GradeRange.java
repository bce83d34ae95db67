package gfx.tick1.command.shared.grader.vpl;

import java.math.BigDecimal;

/**
 * The grades VPL allows an activity ({@code VPL_GRADEMIN} to {@code VPL_GRADEMAX}): a pass is given the
 * maximum, a fail the minimum. Written as plain decimals with a point, as VPL reads a proposed grade
 * with {@code unformat_float}, which would take "7,5" for 7.
 *
 * @param min the grade of a fail
 * @param max the grade of a pass
 */
public record GradeRange(BigDecimal min, BigDecimal max) {

    /** The largest grade accepted, as tick1 grade's --max-grade. */
    private static final BigDecimal MOST = BigDecimal.valueOf(1_000_000);

    public GradeRange {
        if (min.signum() < 0 || max.compareTo(min) <= 0 || max.compareTo(MOST) > 0) {
            throw new IllegalArgumentException("the grades must be from 0 to 1000000, the minimum below the "
                    + "maximum, not " + plain(min) + ":" + plain(max));
        }
    }

    /**
     * The range written {@code MIN:MAX}, each a decimal with a point ({@code 0:10}, {@code 0:7.5}).
     *
     * @throws IllegalArgumentException one line saying what is wrong
     */
    public static GradeRange parse(String text) {
        int colon = text.indexOf(':');
        if (colon < 0) {
            throw new IllegalArgumentException("write the grades as MIN:MAX, such as 0:10, not " + text);
        }
        return new GradeRange(decimal(text.substring(0, colon)), decimal(text.substring(colon + 1)));
    }

    private static BigDecimal decimal(String text) {
        if (!text.strip().matches("[0-9]{1,7}(\\.[0-9]{1,6})?")) {
            throw new IllegalArgumentException("a grade is a decimal with a point, such as 10 or 7.5, not \""
                    + text + "\"");
        }
        return new BigDecimal(text.strip());
    }

    /** The grade for a pass or a fail, as VPL's grade line carries it. */
    public String grade(boolean passed) {
        return plain(passed ? max : min);
    }

    static String plain(BigDecimal value) {
        return value.signum() == 0 ? "0" : value.stripTrailingZeros().toPlainString();
    }
}
