package gfx.tick1.engine.io;

import java.io.PrintWriter;
import java.time.Duration;

/**
 * One updating line on a terminal's standard error ({@code \r} and the new text), shown only when enabled (on a
 * terminal) and, for work that is usually quick, only once it has taken long enough for a person to wonder.
 */
public final class ProgressLine {

    private final PrintWriter err;
    private final boolean enabled;
    private final long showAfterNanos;
    private final long updateEveryNanos;
    private final long start = System.nanoTime();
    private long lastShown;
    private int widest;

    /**
     * @param showAfter   how long the work runs before the line first shows
     * @param updateEvery how long the line stays before it changes again
     */
    public ProgressLine(PrintWriter err, boolean enabled, Duration showAfter, Duration updateEvery) {
        this.err = err;
        this.enabled = enabled;
        this.showAfterNanos = showAfter.toNanos();
        this.updateEveryNanos = updateEvery.toNanos();
    }

    /** Shows {@code text} in place of the line's last one, unless it is too soon. */
    public synchronized void show(String text) {
        long now = System.nanoTime();
        if (!enabled || now - start < showAfterNanos || (widest > 0 && now - lastShown < updateEveryNanos)) {
            return;
        }
        err.print("\r" + text);
        err.flush();
        widest = Math.max(widest, Math.max(1, text.length()));
        lastShown = now;
    }

    /** Clears the line, if it showed, so that what follows starts on a clean one. */
    public synchronized void finish() {
        if (widest > 0) {
            err.print("\r" + " ".repeat(widest) + "\r");
            err.flush();
        }
    }
}
