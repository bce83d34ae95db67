package gfx.tick1.engine.math;

/**
 * An immutable 3-vector of doubles: a point, a direction, or an RGB colour (x, y, z = r, g, b),
 * exactly as the handout's starter code uses it.
 *
 * <p>The arithmetic is written in the same order as the course's starter class (for example
 * {@link #normalised()} divides each component by the magnitude rather than multiplying by its
 * reciprocal), because the reference images must match a plain double-precision implementation
 * bit for bit, and a different rounding order can move a pixel across a truncation boundary.
 */
public final class Vector3 {

    public final double x, y, z;

    public Vector3(double uniform) {
        this(uniform, uniform, uniform);
    }

    public Vector3(double x, double y, double z) {
        this.x = x;
        this.y = y;
        this.z = z;
    }

    public Vector3 add(Vector3 other) {
        return new Vector3(x + other.x, y + other.y, z + other.z);
    }

    public Vector3 subtract(Vector3 other) {
        return new Vector3(x - other.x, y - other.y, z - other.z);
    }

    public Vector3 scale(double scalar) {
        return new Vector3(scalar * x, scalar * y, scalar * z);
    }

    /** Component-wise (Hadamard) product: how a light's colour filters a surface's colour. */
    public Vector3 scale(Vector3 other) {
        return new Vector3(x * other.x, y * other.y, z * other.z);
    }

    public double dot(Vector3 other) {
        return x * other.x + y * other.y + z * other.z;
    }

    public Vector3 cross(Vector3 other) {
        return new Vector3(y * other.z - z * other.y, z * other.x - x * other.z, x * other.y - y * other.x);
    }

    public double magnitude() {
        return Math.sqrt(x * x + y * y + z * z);
    }

    public Vector3 normalised() {
        double magnitude = magnitude();
        return new Vector3(x / magnitude, y / magnitude, z / magnitude);
    }

    /**
     * The mirror image of this vector in the unit normal N: {@code 2 (this . N) N - this}.
     * It is the handout's R for L (footnote 1: a mirror reflection, not a bounce).
     */
    public Vector3 reflectIn(Vector3 N) {
        return N.scale(2 * this.dot(N)).subtract(this);
    }

    /** Packs a colour as 0xRRGGBB; see {@link #toByte(double)} for each channel. */
    public int toRGB() {
        return toByte(x) << 16 | toByte(y) << 8 | toByte(z);
    }

    /**
     * One colour channel as a byte: clamp to [0, 1], times 255, truncated towards zero (the
     * course's {@code (int)} cast, not rounding), so the background 0.1 becomes 25, not 26.
     * NaN clamps to 0 through {@code (int) NaN == 0}.
     */
    public static int toByte(double channel) {
        return (int) (255 * Math.max(0, Math.min(1, channel)));
    }

    public boolean equals(Vector3 other) {
        return other != null && x == other.x && y == other.y && z == other.z;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Vector3 && equals((Vector3) other);
    }

    @Override
    public int hashCode() {
        return Double.hashCode(x) * 961 + Double.hashCode(y) * 31 + Double.hashCode(z);
    }

    @Override
    public String toString() {
        return "(" + x + ", " + y + ", " + z + ")";
    }
}
