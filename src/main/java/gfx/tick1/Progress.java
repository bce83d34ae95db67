package gfx.tick1;

import java.io.PrintWriter;
import java.util.function.IntConsumer;

/**
 * A single updating progress line on standard error, shown only on a terminal and only once a
 * render has taken long enough for a person to wonder (the starter code printed a line per row).
 */
final class Progress implements IntConsumer {

    private static final long SHOW_AFTER_NANOS = 500_000_000L;
    private static final long UPDATE_EVERY_NANOS = 100_000_000L;

    private final PrintWriter err;
    private final int rows;
    private final boolean enabled;
    private final long start = System.nanoTime();
    private long lastShown;
    private boolean shown;

    Progress(PrintWriter err, int rows, boolean enabled) {
        this.err = err;
        this.rows = rows;
        this.enabled = enabled;
    }

    @Override
    public synchronized void accept(int rowsDone) {
        if (!enabled) {
            return;
        }
        long now = System.nanoTime();
        if (now - start < SHOW_AFTER_NANOS || (shown && now - lastShown < UPDATE_EVERY_NANOS)) {
            return;
        }
        err.printf("\rrendering: %3d%%", 100L * rowsDone / rows);
        err.flush();
        shown = true;
        lastShown = now;
    }

    /** Clears the line, so that what follows starts on a clean one. */
    synchronized void finish() {
        if (shown) {
            err.print("\r               \r");
            err.flush();
        }
    }
}
