package gfx.tick1.engine.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.MalformedInputException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import org.junit.jupiter.api.Test;

/** One wording for each way a file operation fails. */
class IoErrorsTest {

    @Test
    void eachKindOfFailureHasItsPlainWords() {
        assertThat(IoErrors.reason(new NoSuchFileException("a.xml"))).isEqualTo("no such file");
        assertThat(IoErrors.reason(new AccessDeniedException("a.xml"))).isEqualTo("permission denied");
        assertThat(IoErrors.reason(new FileAlreadyExistsException("out"))).isEqualTo("exists and is not a folder");
        assertThat(IoErrors.reason(new MalformedInputException(1))).isEqualTo("not UTF-8 text");
    }

    @Test
    void theOperatingSystemsReasonIsKeptWhereThereIsNoPlainerWord() {
        FileSystemException full = new FileSystemException("out.png", null, "No space left on device");
        assertThat(IoErrors.reason(full)).isEqualTo("No space left on device");
        assertThat(IoErrors.reason(new IOException("standard output was closed")))
                .isEqualTo("standard output was closed");
    }

    @Test
    void describeNamesTheFileJavaNamesBeforeTheReason() {
        assertThat(IoErrors.describe(new NoSuchFileException("kit/src"))).isEqualTo("kit/src: no such file");
        assertThat(IoErrors.describe(new IOException("a message of its own"))).isEqualTo("a message of its own");
    }
}
