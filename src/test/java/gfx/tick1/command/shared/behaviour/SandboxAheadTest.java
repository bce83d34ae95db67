package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.SandboxProperties;
import org.junit.jupiter.api.Test;

/** The sandbox made in a thread of its own while the caller works: the same sandbox, or the same refusal. */
@SandboxProperties.Written
class SandboxAheadTest {

    @Test
    void withoutTheSandboxTheMethodsRunUnconfined() throws Exception {
        Sandbox sandbox = SandboxAhead.start(RunIn.OWN_PROCESS).sandbox();

        assertThat(sandbox.enforcement().confined()).as("whether --no-sandbox's sandbox confines the code")
                .isFalse();
    }

    @Test
    void aSandboxThatCannotBeMadeIsRefusedWithItsOwnReasonWhenAskedFor() {
        String property = "tick1.grade.bwrap";
        System.setProperty(property, "/nonexistent/bwrap");
        try {
            SandboxAhead ahead = SandboxAhead.start(RunIn.SANDBOX);

            assertThatThrownBy(ahead::sandbox).as("what asking for a sandbox that cannot be made throws")
                    .isInstanceOf(Sandbox.Unavailable.class);
        } finally {
            System.clearProperty(property);
        }
    }
}
