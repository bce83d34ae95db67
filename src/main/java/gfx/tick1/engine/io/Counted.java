package gfx.tick1.engine.io;

/** A count and its noun, agreeing in number: "1 pixel", "2 pixels", "0 levels". */
public final class Counted {

    private Counted() {
    }

    /** {@code count} and {@code singular}, with an s after it unless the count is exactly 1. */
    public static String of(long count, String singular) {
        return of(count, singular, singular + "s");
    }

    /** {@code count} and the singular or plural noun, as the count asks. */
    public static String of(long count, String singular, String plural) {
        return count + " " + (count == 1 ? singular : plural);
    }
}
