package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the sandbox hides of the grader's own code when that is installed inside the system it
 * shows, and of the organiser's scenes wherever they really are.
 */
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

    @Test
    void aSceneLinkedToAFileDirectlyInTheSystemIsHiddenAsThatFile() throws IOException {
        Path system = Files.createDirectories(dir.resolve("usr"));
        Path real = Files.writeString(system.resolve("hidden.xml"), "<scene/>");
        Path scenes = Files.createDirectories(dir.resolve("home/scenes"));
        Path link = Files.createSymbolicLink(scenes.resolve("hidden.xml"), real);

        assertThat(Sandbox.secretsShown(List.of(system.toRealPath()), List.of(scenes, link)))
                .as("the scenes folder is not shown; the file it links to is")
                .containsExactly(new Sandbox.Secret(real.toRealPath(), false));
    }

    @Test
    void aScenesFolderInTheSystemIsHiddenAsAFolderBeforeAnyFile() throws IOException {
        Path system = Files.createDirectories(dir.resolve("usr"));
        Path scenes = Files.createDirectories(system.resolve("share/scenes"));
        Path scene = Files.writeString(scenes.resolve("hidden.xml"), "<scene/>");

        assertThat(Sandbox.secretsShown(List.of(system.toRealPath()), List.of(scene, scenes))).containsExactly(
                new Sandbox.Secret(scenes.toRealPath(), true), new Sandbox.Secret(scene.toRealPath(), false));
    }

    @Test
    void aScenesFolderThatHoldsTheSystemIsRefusedInOneLine() throws IOException {
        Path system = Files.createDirectories(dir.resolve("usr"));

        assertThatThrownBy(() -> Sandbox.secretsShown(List.of(system.toRealPath()), List.of(dir)))
                .isInstanceOf(Sandbox.CannotHide.class)
                .hasMessage(dir + ": the sandbox shows the student's code what is in " + system.toRealPath()
                        + ", so it cannot hide this folder's scenes from it: give the scenes a folder of their own");
    }

    @Test
    void aScenesFolderThatHoldsTheJdkTheRunsNeedIsRefused() throws IOException {
        // On Debian the JDK is in /usr/lib/jvm: hiding that folder under an empty one leaves the
        // sandbox no java to run, and every student fails ("could not be compiled") instead.
        Path jdkFolder = Path.of(System.getProperty("java.home")).toRealPath().getParent();

        assertThatThrownBy(() -> Sandbox.unconfined().hiding(List.of(jdkFolder)))
                .as("--scenes " + jdkFolder + ", the folder of the JDK the sandbox runs")
                .isInstanceOf(Sandbox.CannotHide.class);
    }

    @Test
    void aScenesFolderInsideAFolderOfLibrariesTheRunsNeedIsRefused() throws IOException {
        // Any folder of /usr/lib may hold a library the JVM loads (Debian's libc and libz are in
        // /usr/lib/x86_64-linux-gnu): hidden under an empty folder, every run would fail.
        Path jdk = Path.of(System.getProperty("java.home")).toRealPath();
        Path inside;
        try (var folders = Files.list(Path.of("/usr/lib"))) {
            inside = folders.filter(Files::isDirectory).filter(folder -> !jdk.startsWith(folder)).sorted()
                    .findFirst().orElseThrow();
        }

        assertThatThrownBy(() -> Sandbox.unconfined().hiding(List.of(inside)))
                .as("--scenes " + inside + ", a folder inside /usr/lib")
                .isInstanceOf(Sandbox.CannotHide.class);
    }
}
