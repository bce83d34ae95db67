package gfx.tick1.command.shared.grader.sandbox;

import org.junit.jupiter.api.extension.ConditionEvaluationResult;
import org.junit.jupiter.api.extension.ExecutionCondition;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * Skips the tests of a class that grade in the sandbox where none can be made (no bubblewrap, or a container or a
 * chroot whose kernel refuses it namespaces), with the one line tick1 says of it and what to do. Asked once.
 */
public final class SandboxNeeded implements ExecutionCondition {

    private static volatile String unavailable;
    private static volatile boolean asked;

    @Override
    public ConditionEvaluationResult evaluateExecutionCondition(ExtensionContext context) {
        String why = why();
        return why == null ? ConditionEvaluationResult.enabled("a sandbox can be made here")
                : ConditionEvaluationResult.disabled("needs the sandbox: " + why);
    }

    /** Whether the tests run as root, whose sandbox runs the code as another user (tick1's own answer). */
    public static boolean root() {
        return ThisUser.root();
    }

    /** Whether a sandbox can be made on this machine (asked once). */
    public static boolean available() {
        return why() == null;
    }

    private static synchronized String why() {
        if (!asked) {
            try {
                Sandbox.confined();
            } catch (Sandbox.Unavailable e) {
                unavailable = e.getMessage() + (e.remedy() == null ? "" : ": " + e.remedy());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                unavailable = "interrupted while making one";
            }
            asked = true;
        }
        return unavailable;
    }
}
