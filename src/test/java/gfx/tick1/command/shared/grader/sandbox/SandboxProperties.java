package gfx.tick1.command.shared.grader.sandbox;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.parallel.ResourceAccessMode;
import org.junit.jupiter.api.parallel.ResourceLock;
import org.junit.jupiter.api.parallel.Resources;

/**
 * The system properties {@link Sandbox#confined()} reads (which bubblewrap, whether runs get output disks of their
 * own), as a resource of the test classes that run side by side: a class that sets one for a test is never run
 * beside a class that grades, diffs or probes in the tests' own JVM, which would then find no sandbox, or a
 * different one. A test that gives such a property to a tick1 in a JVM of its own ({@code CliRun.inJvm}) needs
 * neither.
 */
public final class SandboxProperties {

    private SandboxProperties() {
    }

    /** On a test class that makes sandboxes in the tests' JVM: it runs beside others that do, never beside a setter. */
    @Target(ElementType.TYPE)
    @Retention(RetentionPolicy.RUNTIME)
    @ResourceLock(value = Resources.SYSTEM_PROPERTIES, mode = ResourceAccessMode.READ)
    public @interface Read {
    }

    /** On a test class one of whose tests sets a property the sandbox reads: no class that reads one runs beside it. */
    @Target(ElementType.TYPE)
    @Retention(RetentionPolicy.RUNTIME)
    @ResourceLock(value = Resources.SYSTEM_PROPERTIES, mode = ResourceAccessMode.READ_WRITE)
    public @interface Written {
    }
}
