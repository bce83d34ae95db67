package gfx.tick1.command.shared.grader.cohort;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A stored result that cannot be read as one is no result: its submission is graded again, and the run goes on. */
class ResultStoreDamagedTest {

    private static final Submission SUBMISSION = new Submission("Bo_8_assignsubmission_file", "8", "Bo", null,
            null, null);

    @TempDir
    Path state;

    @Test
    void aStoredResultWithBytesThatAreNotUtf8IsNoResult() throws IOException {
        ResultStore store = new ResultStore(state);
        store.save("key", new StudentResult(SUBMISSION, new StudentResult.Summary(true, 2, 2,
                Category.Outcome.PASSED, "PASSED"), List.of(), Duration.ofMillis(3)), store.newEntry());
        Files.write(store.folderOf("key").resolve("result.properties"), new byte[] {(byte) 0xff, (byte) 0xfe, '\n'},
                StandardOpenOption.APPEND);

        assertThat(store.load("key", SUBMISSION)).as("a damaged stored result").isNull();
    }

    @Test
    void aStoredResultWithAMalformedEscapeIsNoResult() throws IOException {
        ResultStore store = new ResultStore(state);
        store.save("key", passed(3), store.newEntry());
        Files.writeString(store.folderOf("key").resolve("result.properties"), "reason=\\u12\n",
                StandardOpenOption.APPEND);

        assertThat(store.load("key", SUBMISSION)).as("a stored result damaged into a malformed escape").isNull();
    }

    @Test
    void aDamagedStoredResultIsReplacedByTheNextResultSavedUnderItsKey() throws IOException {
        ResultStore store = new ResultStore(state);
        store.save("key", passed(3), store.newEntry());
        Files.write(store.folderOf("key").resolve("result.properties"), new byte[] {(byte) 0xff, (byte) 0xfe, '\n'},
                StandardOpenOption.APPEND);

        store.save("key", passed(5), store.newEntry());

        assertThat(store.load("key", SUBMISSION)).as("the result stored over a damaged one").isNotNull()
                .extracting(StudentResult::time).isEqualTo(Duration.ofMillis(5));
    }

    @Test
    void aStoredResultDamagedIntoAFileIsReplacedByTheNextResultSavedUnderItsKey() throws IOException {
        ResultStore store = new ResultStore(state);
        Files.writeString(store.folderOf("key"), "not a folder");

        store.save("key", passed(5), store.newEntry());

        assertThat(store.load("key", SUBMISSION)).as("the result stored over a file at its key").isNotNull()
                .extracting(StudentResult::time).isEqualTo(Duration.ofMillis(5));
    }

    private static StudentResult passed(long millis) {
        return new StudentResult(SUBMISSION, new StudentResult.Summary(true, 2, 2, Category.Outcome.PASSED, "PASSED"),
                List.of(), Duration.ofMillis(millis));
    }
}
