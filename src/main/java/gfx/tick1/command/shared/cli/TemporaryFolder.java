package gfx.tick1.command.shared.cli;

import gfx.tick1.engine.io.IoErrors;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Java's temporary folder (java.io.tmpdir), where grading and the behaviour check put their work, tried before
 * they start: a folder that is missing, is a file, is read-only or full would otherwise fail deep in the work,
 * where the error names a file inside it, or blames the sandbox. Trying costs one empty file made and deleted.
 */
public final class TemporaryFolder {

    private TemporaryFolder() {
    }

    /** The one line that says why the temporary folder cannot hold tick1's work, and what to do; else empty. */
    public static Optional<String> problem() {
        return problem(Path.of(System.getProperty("java.io.tmpdir", "")));
    }

    /** As {@link #problem()}, for the temporary folder {@code folder}. */
    static Optional<String> problem(Path folder) {
        try {
            Files.delete(Files.createTempFile(folder, "tick1-try-", ".tmp"));
            return Optional.empty();
        } catch (IOException | SecurityException e) {
            String why = !Files.exists(folder) ? "no such folder" : !Files.isDirectory(folder) ? "not a folder"
                    : e instanceof IOException io ? IoErrors.reason(io) : "permission denied";
            return Optional.of("the temporary folder " + folder + " (java.io.tmpdir) cannot be used: " + why
                    + "; give tick1 a folder it can write with " + Invocation.javaOption("-Djava.io.tmpdir=FOLDER"));
        }
    }
}
