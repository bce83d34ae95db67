package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;

/**
 * The sandbox where the methods are to run ({@link RunIn}), made in a thread of its own from the
 * moment the caller starts it: making it waits on processes (bubblewrap's self-test, a trial mount),
 * which need not hold up the caller's own work, such as {@code tick1 diff}'s parsing of the files.
 */
public final class SandboxAhead {

    private final FutureTask<Sandbox> making;

    private SandboxAhead(RunIn where) {
        making = new FutureTask<>(where::sandbox);
    }

    /** Starts making the sandbox of {@code where}. */
    public static SandboxAhead start(RunIn where) {
        SandboxAhead ahead = new SandboxAhead(where);
        Thread thread = new Thread(ahead.making, "tick1 sandbox");
        thread.setDaemon(true);
        thread.start();
        return ahead;
    }

    /**
     * The sandbox, once it is made.
     *
     * @throws Sandbox.Unavailable when it cannot be made here
     */
    Sandbox sandbox() throws Sandbox.Unavailable, InterruptedException {
        try {
            return making.get();
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof Sandbox.Unavailable unavailable) {
                throw unavailable;
            }
            if (cause instanceof InterruptedException interrupted) {
                throw interrupted;
            }
            if (cause instanceof RuntimeException unchecked) {
                throw unchecked;
            }
            if (cause instanceof Error error) {
                throw error;
            }
            throw new IllegalStateException(cause);
        }
    }
}
