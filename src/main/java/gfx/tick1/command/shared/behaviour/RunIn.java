package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.grader.sandbox.Sandbox;

/**
 * Where the student's methods run when their behaviour is checked on its own: in the sandbox,
 * as {@code grade} runs them, or, for one's own code on a machine without bubblewrap
 * ({@code --no-sandbox}), in a JVM of their own held only to the time limit and the heap
 * ({@link BehaviourCheck#LIMITS}).
 */
public enum RunIn {

    /** The sandbox: the only choice for code that is not the user's own. */
    SANDBOX,

    /** A JVM of their own with no sandbox: the user's own code, with {@code --no-sandbox}. */
    OWN_PROCESS;

    /** The sandbox to run in. */
    Sandbox sandbox() throws Sandbox.Unavailable, InterruptedException {
        return this == SANDBOX ? Sandbox.confined() : Sandbox.unconfined();
    }
}
