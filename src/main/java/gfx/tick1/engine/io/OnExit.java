package gfx.tick1.engine.io;

import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Clean-up that must happen however the work ends: when {@link #now()} is called at its end, or from a shutdown
 * hook if the JVM is stopped first (Ctrl-C, SIGTERM, {@code System.exit}). The action runs once, whichever comes
 * first; only a hard kill (SIGKILL, power loss) skips it.
 */
public final class OnExit {

    private final Runnable action;
    private final AtomicBoolean ran = new AtomicBoolean();
    private final Thread hook;

    private OnExit(Runnable action, String name) {
        this.action = action;
        this.hook = new Thread(this::runOnce, name);
    }

    /** Runs {@code action} on {@link #now()}, or at shutdown if that comes first. */
    public static OnExit run(String name, Runnable action) {
        OnExit onExit = new OnExit(action, name);
        Runtime.getRuntime().addShutdownHook(onExit.hook);
        return onExit;
    }

    private void runOnce() {
        if (ran.compareAndSet(false, true)) {
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
