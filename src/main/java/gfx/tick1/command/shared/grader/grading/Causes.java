package gfx.tick1.command.shared.grader.grading;

/** The failure of work done on another thread, thrown here as that thread threw it. */
final class Causes {

    private Causes() {
    }

    /** Throws {@code cause} as it is where it is unchecked (a RuntimeException or an Error); else returns. */
    static void throwIfUnchecked(Throwable cause) {
        if (cause instanceof RuntimeException unchecked) {
            throw unchecked;
        }
        if (cause instanceof Error error) {
            throw error;
        }
    }
}
