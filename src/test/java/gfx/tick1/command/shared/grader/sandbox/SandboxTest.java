package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assumptions.assumeThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * Which of the organiser's scenes the sandbox refuses to hide because the runs need what is in
 * them; every other file of the host's the runs never see ({@link SystemFilesTest}).
 */
class SandboxTest {

    @TempDir
    Path dir;

    @Test
    void aScenesFolderThatHoldsAFileTheRunsSeeIsRefusedInOneLine() throws IOException {
        Path library = Files.writeString(Files.createDirectories(dir.resolve("usr/lib")).resolve("libz.so.1"), "elf");
        SystemFiles system = SystemFiles.following(List.of(library));
        Path jdk = Files.createDirectories(dir.resolve("jdk"));

        Path usr = dir.resolve("usr");

        assertThatThrownBy(() -> Secrets.refuseWhatTheRunsSee(List.of(usr), system, jdk.toRealPath()))
                .isInstanceOf(Sandbox.CannotHide.class)
                .hasMessage(usr + ": the runs need " + library.toRealPath() + ", so tick1 cannot hide this folder's "
                        + "scenes from the student's code without stopping every run: give the scenes a folder of "
                        + "their own");
    }

    @Test
    void aScenesFolderThatHoldsTheJdkTheRunsNeedIsRefused() throws IOException {
        // On Debian the JDK is in /usr/lib/jvm: the runs need it, so its folder cannot be hidden.
        Path jdkFolder = Path.of(System.getProperty("java.home")).toRealPath().getParent();

        assertThatThrownBy(() -> Sandbox.unconfined().hiding(List.of(jdkFolder)))
                .as("--scenes " + jdkFolder + ", the folder of the JDK the sandbox runs")
                .isInstanceOf(Sandbox.CannotHide.class);
    }

    @Test
    void aSceneInsideTheJdkIsRefused() throws IOException {
        Path jdk = Files.createDirectories(dir.resolve("jdk"));
        Path scenes = Files.createDirectories(jdk.resolve("lib/scenes"));
        Path scene = Files.writeString(scenes.resolve("hidden.xml"), "<scene/>");

        assertThatThrownBy(() -> Secrets.refuseWhatTheRunsSee(List.of(scene), SystemFiles.following(List.of()),
                jdk.toRealPath()))
                .as("a scene in the JDK's folder, which the runs see")
                .isInstanceOf(Sandbox.CannotHide.class)
                .hasMessageContaining("this scene from the student's code");
    }

    @Test
    void aScenesFolderBesideTheFilesTheRunsSeeIsNotRefused() throws IOException {
        // A folder of /usr/lib that holds none of the libraries java loads: the runs see nothing of it.
        Path library = Files.writeString(Files.createDirectories(dir.resolve("usr/lib")).resolve("libz.so.1"), "elf");
        Path scenes = Files.createDirectories(dir.resolve("usr/lib/scenes"));
        Path jdk = Files.createDirectories(dir.resolve("jdk"));

        assertThatCode(() -> Secrets.refuseWhatTheRunsSee(List.of(scenes), SystemFiles.following(List.of(library)),
                jdk.toRealPath()))
                .as("--scenes " + scenes + ", beside " + library).doesNotThrowAnyException();
    }

    @ExtendWith(SandboxNeeded.class)
    @Test
    void theUserTheCodeRunsAsTellsNothingOfTheGradersProcessId() throws Exception {
        Sandbox first = Sandbox.confined();
        Sandbox second = Sandbox.confined();
        assumeThat(first.runUser()).as("the grader is root, so the code runs as a user of its own")
                .isGreaterThanOrEqualTo(RunUsers.FIRST_UID);

        // Made from this process's id, both would be the same user; the code reads its user id,
        // and a process id would tell it how many processes the machine started since an earlier grade.
        assertThat(List.of(first.runUser(), second.runUser())).as("the users of two sandboxes of one grader")
                .doesNotHaveDuplicates();
    }
}
