package gfx.tick1.command.shared.grader.cohort;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Two grades writing into the same report folder at once: each result being written carries the id of the
 * process writing it, and a store opened by one run deletes only what runs whose process is gone left half
 * written, never what a live run is writing.
 */
class ResultStoreConcurrentRunsTest {

    @TempDir
    Path state;

    @Test
    void aResultThatALiveRunIsWritingIsLeftAlone() throws Exception {
        // These tests' JVM is a live Java program, as a tick1 run is.
        Path writing = Files.createDirectory(state.resolve(".writing-" + ProcessHandle.current().pid() + "-1"));

        new ResultStore(state);

        assertThat(writing).as("a result a live run is writing").isDirectory();
    }

    @Test
    void aResultThatARunWhoseProcessIsGoneLeftHalfWrittenIsDeleted() throws Exception {
        Process done = new ProcessBuilder("/bin/true").start();
        assertThat(done.waitFor(30, TimeUnit.SECONDS)).isTrue();
        Path writing = Files.createDirectory(state.resolve(".writing-" + done.pid() + "-1"));
        Files.writeString(writing.resolve("result.properties"), "passed=true");

        new ResultStore(state);

        assertThat(writing).as("a result half written by a run that is gone").doesNotExist();
    }

    @Test
    void aResultBeingWrittenIsNamedWithTheIdOfTheProcessWritingIt() throws Exception {
        Path entry = new ResultStore(state).newEntry();

        assertThat(entry.getFileName().toString()).startsWith(".writing-" + ProcessHandle.current().pid() + "-");
    }
}
