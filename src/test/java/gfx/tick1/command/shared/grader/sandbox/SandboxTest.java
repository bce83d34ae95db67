package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What the sandbox hides of the grader's own code when that is installed inside the system it shows. */
class SandboxTest {

    @TempDir
    Path dir;

    @Test
    void theFoldersOfTheGradersJarsAndClassFoldersInsideTheSystemAreHidden() throws IOException {
        Path system = Files.createDirectories(dir.resolve("usr"));
        Path lib = Files.createDirectories(system.resolve("share/tick1/lib"));
        Path jar = Files.writeString(lib.resolve("tick1.jar"), "a jar");
        Path picocli = Files.writeString(lib.resolve("picocli.jar"), "another jar");
        Path classes = Files.createDirectories(system.resolve("lib/tick1/classes"));
        Path elsewhere = Files.writeString(Files.createDirectories(dir.resolve("home")).resolve("tick1.jar"), "a jar");

        assertThat(Sandbox.foldersUnder(system.toRealPath(), List.of(jar, picocli, classes, elsewhere,
                dir.resolve("missing.jar"))))
                .containsExactly(lib.toRealPath(), classes.toRealPath());
    }

    @Test
    void theSystemFolderItselfIsNeverHidden() throws IOException {
        Path system = Files.createDirectories(dir.resolve("usr"));
        Path jar = Files.writeString(system.resolve("tick1.jar"), "a jar");
        assertThat(Sandbox.foldersUnder(system.toRealPath(), List.of(jar, system))).isEmpty();
    }
}
