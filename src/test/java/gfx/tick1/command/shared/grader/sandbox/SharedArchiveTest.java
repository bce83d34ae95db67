package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The class data sharing archive a cohort's runs map is made by a run of the starter kit that
 * renders its scene, so that it holds the image classes and ImageIO's PNG writer as well as javac.
 */
class SharedArchiveTest {

    @TempDir
    Path dir;

    @Test
    void theArchiveIsMadeByARunThatRendersItsSceneWithTheStarterKit() throws Exception {
        Sandbox sandbox;
        try {
            sandbox = Sandbox.confined();
        } catch (Sandbox.Unavailable e) {
            assumeThat(e.getMessage()).as("bubblewrap is needed to make the archive").isNull();
            return;
        }
        // The sandbox's user must pass through to the folders, and read the harness.
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx--x--x"));
        Path harness = Files.createDirectory(dir.resolve("harness"));
        StudentProcess.writeHarness(harness);
        Files.setPosixFilePermissions(harness, PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.setPosixFilePermissions(harness.resolve(HarnessJvm.HARNESS_JAR),
                PosixFilePermissions.fromString("r--r--r--"));
        Path archive = Files.createDirectory(dir.resolve("archive"));
        StudentProcess process = new StudentProcess(sandbox, harness, 512);

        StudentProcess withArchive = process.withSharedArchive(archive, Files.createDirectory(dir.resolve("work")));

        assertThat(withArchive).as("the archive's run must render its scene, or no archive is kept")
                .isNotSameAs(process);
        assertThat(archive.resolve(HarnessJvm.SHARED_ARCHIVE)).isRegularFile();
    }
}
