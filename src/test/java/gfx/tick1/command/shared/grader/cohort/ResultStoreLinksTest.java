package gfx.tick1.command.shared.grader.cohort;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The cohort's state folder (in the report folder) follows no link: neither the folder itself, nor a stored result's
 * folder. A link is replaced, or read as no result; what it names is never deleted, read or written.
 */
class ResultStoreLinksTest {

    private static final String KEY = "0123456789abcdef";
    private static final Submission SUBMISSION = new Submission("Ann_7_assignsubmission_file", "7", "Ann", null,
            null, null);
    private static final StudentResult RESULT = new StudentResult(SUBMISSION, new StudentResult.Summary(true, 1, 1,
            Category.Outcome.PASSED, "fine"), List.of(), Duration.ofMillis(5));

    @TempDir
    Path temp;
    private Path elsewhere;

    @BeforeEach
    void aFolderElsewhere() throws IOException {
        elsewhere = Files.createDirectories(temp.resolve("elsewhere"));
        // What a stopped run leaves half-written, and what the store deletes at its start.
        Files.createDirectories(elsewhere.resolve(".writing-1"));
        Files.writeString(elsewhere.resolve(".writing-1/result.properties"), "precious");
    }

    @Test
    void aStateFolderThatIsALinkIsReplacedNotFollowed() throws IOException {
        Path state = Files.createSymbolicLink(temp.resolve("state"), elsewhere);

        ResultStore store = new ResultStore(state);
        Path entry = store.newEntry();
        store.save(KEY, RESULT, entry);

        assertThat(elsewhere.resolve(".writing-1/result.properties")).as("what the link named").hasContent("precious");
        assertThat(Files.isSymbolicLink(state)).as("still a link").isFalse();
        assertThat(store.load(KEY, SUBMISSION)).as("the result stored").isNotNull();
        assertThat(elsewhere.resolve(KEY)).doesNotExist();
    }

    @Test
    void aStoredResultThatIsALinkIsNoResultAndIsReplacedWhenStored() throws IOException {
        Path state = temp.resolve("state");
        ResultStore store = new ResultStore(state);
        Path forged = Files.createDirectories(elsewhere.resolve("forged"));
        Path entry = store.newEntry();
        store.save(KEY, RESULT, entry);
        Files.move(state.resolve(KEY), forged.resolve("x"));
        Files.move(forged.resolve("x/result.properties"), forged.resolve("result.properties"));
        Files.createSymbolicLink(state.resolve(KEY), forged);

        assertThat(store.load(KEY, SUBMISSION)).as("a result read through a link").isNull();
        store.save(KEY, RESULT, store.newEntry());
        assertThat(Files.isSymbolicLink(state.resolve(KEY))).as("still a link").isFalse();
        assertThat(store.load(KEY, SUBMISSION)).isNotNull();
    }
}
