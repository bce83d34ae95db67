package gfx.tick1.engine.math;

/**
 * A real number held as the unevaluated sum hi + lo of two doubles with |lo| &lt;= ulp(hi) / 2:
 * about 106 significant bits, twice a double's. The truth renderer computes in it; the robust
 * intersection borrows its error-free transformations ({@link #twoSum}, {@link #twoProduct}).
 *
 * <p>The algorithms are the classical ones (Dekker 1971; Knuth's TwoSum; Bailey's QD library
 * "accurate" addition; one Newton step for division and square root): each result is within a few
 * units of 2^-104 of the exact one, relative to the operands' magnitudes. Nothing here guards
 * against overflow or subnormal operands; the scene loader keeps every input far from both.
 */
public final class DoubleDouble implements Comparable<DoubleDouble> {

    public static final DoubleDouble ZERO = new DoubleDouble(0, 0);
    public static final DoubleDouble ONE = new DoubleDouble(1, 0);
    /** pi to about 32 digits: Math.PI plus the next 53 bits of pi. */
    public static final DoubleDouble PI = new DoubleDouble(Math.PI, 1.2246467991473532e-16);

    public final double hi, lo;

    private DoubleDouble(double hi, double lo) {
        this.hi = hi;
        this.lo = lo;
    }

    /** The exact value of a double. */
    public static DoubleDouble of(double value) {
        return new DoubleDouble(value, 0);
    }

    // --- Error-free transformations: the exact result as a rounded value plus its rounding error.

    /** The rounding error of a + b: a + b == fl(a + b) + twoSumError(a, b) exactly (Knuth). */
    public static double twoSumError(double a, double b, double sum) {
        double bVirtual = sum - a;
        return (a - (sum - bVirtual)) + (b - bVirtual);
    }

    /** a + b exactly, as a normalised double-double. */
    public static DoubleDouble twoSum(double a, double b) {
        double sum = a + b;
        return new DoubleDouble(sum, twoSumError(a, b, sum));
    }

    /** a * b exactly: fma computes a * b - fl(a * b) with a single rounding, which is exact. */
    public static DoubleDouble twoProduct(double a, double b) {
        double product = a * b;
        return new DoubleDouble(product, Math.fma(a, b, -product));
    }

    /** Renormalises hi + lo when |hi| &gt;= |lo| is already known (Dekker's FastTwoSum). */
    private static DoubleDouble fastTwoSum(double hi, double lo) {
        double sum = hi + lo;
        return new DoubleDouble(sum, lo - (sum - hi));
    }

    // --- Arithmetic.

    public DoubleDouble add(DoubleDouble other) {
        double s = hi + other.hi;
        double e = twoSumError(hi, other.hi, s);
        double t = lo + other.lo;
        double f = twoSumError(lo, other.lo, t);
        e += t;
        DoubleDouble head = fastTwoSum(s, e);
        return fastTwoSum(head.hi, head.lo + f);
    }

    public DoubleDouble add(double other) {
        return add(of(other));
    }

    public DoubleDouble negate() {
        return new DoubleDouble(-hi, -lo);
    }

    public DoubleDouble subtract(DoubleDouble other) {
        return add(other.negate());
    }

    public DoubleDouble multiply(DoubleDouble other) {
        double p = hi * other.hi;
        double e = Math.fma(hi, other.hi, -p);
        e += hi * other.lo + lo * other.hi;
        return fastTwoSum(p, e);
    }

    public DoubleDouble multiply(double other) {
        return multiply(of(other));
    }

    /** Long division: three double quotients, each correcting the remainder of the one before. */
    public DoubleDouble divide(DoubleDouble divisor) {
        double q1 = hi / divisor.hi;
        DoubleDouble r = subtract(divisor.multiply(q1));
        double q2 = r.hi / divisor.hi;
        r = r.subtract(divisor.multiply(q2));
        double q3 = r.hi / divisor.hi;
        return fastTwoSum(q1, q2).add(q3);
    }

    /** The square root: one Newton step x + (this - x^2) / 2x from the double root x doubles its bits. */
    public DoubleDouble sqrt() {
        if (hi <= 0) {
            return hi == 0 ? ZERO : new DoubleDouble(Double.NaN, Double.NaN);
        }
        double x = Math.sqrt(hi);
        DoubleDouble residual = subtract(twoProduct(x, x));
        return fastTwoSum(x, residual.hi / (2 * x));
    }

    public int signum() {
        return hi != 0 ? (int) Math.signum(hi) : (int) Math.signum(lo);
    }

    public DoubleDouble abs() {
        return signum() < 0 ? negate() : this;
    }

    public double doubleValue() {
        return hi + lo;
    }

    /** The largest integer not above this value (which must fit in a long). */
    public long floor() {
        double f = Math.floor(hi);
        if (f != hi) {
            return (long) f;
        }
        // hi is an integer: the sign of lo decides.
        return (long) hi + (long) Math.floor(lo);
    }

    @Override
    public int compareTo(DoubleDouble other) {
        return subtract(other).signum();
    }

    public DoubleDouble min(DoubleDouble other) {
        return compareTo(other) <= 0 ? this : other;
    }

    public DoubleDouble max(DoubleDouble other) {
        return compareTo(other) >= 0 ? this : other;
    }

    @Override
    public String toString() {
        return hi + " + " + lo;
    }
}
