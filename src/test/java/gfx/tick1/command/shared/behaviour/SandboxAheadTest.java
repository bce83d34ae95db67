package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import org.junit.jupiter.api.Test;

/**
 * The sandbox made in a thread of its own while the caller works: the same sandbox. A sandbox that cannot be
 * made is refused with its own reason where diff asks for it (DiffCommandTest, without bubblewrap and where the
 * kernel refuses namespaces, each in a JVM of its own).
 */
class SandboxAheadTest {

    @Test
    void withoutTheSandboxTheMethodsRunUnconfined() throws Exception {
        Sandbox sandbox = SandboxAhead.start(RunIn.OWN_PROCESS).sandbox();

        assertThat(sandbox.enforcement().confined()).as("whether --no-sandbox's sandbox confines the code")
                .isFalse();
    }
}
