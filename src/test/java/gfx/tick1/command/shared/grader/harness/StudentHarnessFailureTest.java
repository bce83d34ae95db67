package gfx.tick1.command.shared.grader.harness;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What the harness writes of an exception the student's code threw: the grader reads it as the scene's failure. */
class StudentHarnessFailureTest {

    @TempDir
    Path dir;

    private String written(Throwable failure) throws IOException {
        Path file = dir.resolve("0.error");
        StudentHarness.writeFailure(file, failure);
        return Files.readString(file, StandardCharsets.UTF_8);
    }

    @Test
    void aMessageWithALoneSurrogateIsWrittenWithAReplacement() throws IOException {
        assertThat(written(new IllegalStateException("half \uD800 a pair"))).as("what the harness wrote")
                .startsWith("java.lang.IllegalStateException: half ? a pair");
    }

    @Test
    void anExceptionWhoseToStringThrowsIsWrittenAsItsClassName() throws IOException {
        Throwable hostile = new HostileException();

        assertThat(written(hostile)).as("what the harness wrote").isEqualTo(HostileException.class.getName());
    }

    @Test
    void theHeapsOutOfMemoryErrorSaysTheMemoryLimitWasReached() throws IOException {
        assertThat(written(new OutOfMemoryError("Java heap space"))).as("what the harness wrote")
                .startsWith("java.lang.OutOfMemoryError: Java heap space (the memory limit was reached)");
        assertThat(written(new OutOfMemoryError("Metaspace"))).as("what the harness wrote")
                .startsWith("java.lang.OutOfMemoryError: Metaspace (the memory limit was reached)");
    }

    @Test
    void noNativeThreadIsNotCalledTheMemoryLimit() throws IOException {
        // HotSpot's message where a thread cannot be started (the limit on threads, or the machine's memory).
        String message = "unable to create native thread: possibly out of memory or process/resource limits reached";

        assertThat(written(new OutOfMemoryError(message))).as("what the harness wrote")
                .startsWith("java.lang.OutOfMemoryError: " + message).doesNotContain("memory limit was reached");
    }

    /** An exception of the student's whose own toString throws. */
    private static final class HostileException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        @Override
        public String toString() {
            throw new IllegalStateException("no");
        }
    }
}
