package gfx.tick1.engine.io;

import java.io.InterruptedIOException;

/**
 * Clean-up that must happen however the work ends: when {@link #now()} is called at its end, or from a shutdown
 * hook if the JVM is stopped first (Ctrl-C, SIGTERM, {@code System.exit}). The action runs once, whichever comes
 * first, and the other waits for it to finish (the JVM ends when its hooks do); only a hard kill (SIGKILL, power
 * loss) skips it.
 */
public final class OnExit {

    private final Runnable action;
    /** Whether the action has run, or runs: guarded by this. */
    private boolean ran;
    private final Thread hook;

    private OnExit(Runnable action, String name) {
        this.action = action;
        this.hook = new Thread(this::runOnce, name);
    }

    /**
     * Runs {@code action} on {@link #now()}, or at shutdown if that comes first. Asked for once the JVM is stopping,
     * when no hook can be added, it runs the action at once and throws: the work it was to clean up after must not
     * begin, since the JVM may end part way through it.
     *
     * @throws InterruptedIOException if the JVM is stopping
     */
    public static OnExit run(String name, Runnable action) throws InterruptedIOException {
        OnExit onExit = new OnExit(action, name);
        try {
            Runtime.getRuntime().addShutdownHook(onExit.hook);
        } catch (IllegalStateException e) {
            action.run();
            throw new InterruptedIOException("tick1 is stopping (Ctrl-C or SIGTERM)");
        }
        return onExit;
    }

    /** Whether the JVM is stopping: running its shutdown hooks, after which it ends whatever else runs. */
    public static boolean stopping() {
        Thread probe = new Thread(() -> { });
        try {
            Runtime.getRuntime().addShutdownHook(probe);
            Runtime.getRuntime().removeShutdownHook(probe);
            return false;
        } catch (IllegalStateException e) {
            return true;
        }
    }

    private synchronized void runOnce() {
        if (!ran) {
            ran = true;
            action.run();
        }
    }

    /** Runs the action now (in a {@code finally}), unless the shutdown hook ran it. */
    public void now() {
        runOnce();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // The JVM is shutting down: the hook runs (or ran) anyway, and does nothing twice.
        }
    }
}
