package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.command.shared.grader.harness.StudentHarness;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The class data sharing archive a cohort's runs map is made by a run of the starter kit that
 * renders its scene, so that it holds the image classes and ImageIO's PNG writer as well as javac;
 * and it fits every harness jar written for the same classes, not only the one it was made with.
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
        WorkFolder.readableByAll(harness);
        Path archive = Files.createDirectory(dir.resolve("archive"));
        StudentProcess process = new StudentProcess(sandbox, harness, 512);

        StudentProcess withArchive = process.withSharedArchive(archive, Files.createDirectory(dir.resolve("work")));

        assertThat(withArchive).as("the archive's run must render its scene, or no archive is kept")
                .isNotSameAs(process);
        assertThat(archive.resolve(HarnessJvm.SHARED_ARCHIVE)).isRegularFile();
    }

    @Test
    void anArchiveMadeWithOneHarnessJarFitsTheJarWrittenAgain() throws Exception {
        Path harness = Files.createDirectory(dir.resolve("harness"));
        Path jar = harness.resolve(HarnessJvm.HARNESS_JAR);
        Path archive = dir.resolve(HarnessJvm.SHARED_ARCHIVE);
        StudentProcess.writeHarness(harness);
        // The harness, given no arguments, fails as it reads the first (its exit status is not checked), its class
        // loaded from the jar by then; the archive is written as the JVM ends, and names the jar.
        java("-XX:ArchiveClassesAtExit=" + archive, "-Xlog:cds=off", "-cp", jar.toString(),
                StudentHarness.class.getName());
        assertThat(archive).as("the archive made with the first jar").isRegularFile();
        byte[] first = Files.readAllBytes(jar);
        FileTime firstTime = Files.getLastModifiedTime(jar);
        Files.delete(jar);

        StudentProcess.writeHarness(harness);
        // With -Xshare:on Java refuses to start when it cannot map the archive: a jar of another size or time
        // (in whole seconds, so the times are compared here too).
        Run run = java("-Xshare:on", "-XX:SharedArchiveFile=" + archive, "-cp", jar.toString(), "-version");

        assertThat(Files.readAllBytes(jar)).as("the jar written again, byte for byte").isEqualTo(first);
        assertThat(Files.getLastModifiedTime(jar)).as("the time of the jar written again").isEqualTo(firstTime);
        assertThat(run.status()).as("java mapping the archive with the jar written again; it printed:%n%s",
                run.printed()).isZero();
    }

    private record Run(int status, String printed) {
    }

    private Run java(String... arguments) throws Exception {
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        command.addAll(List.of(arguments));
        Path output = dir.resolve("java.txt");
        Process process = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null"))).start();
        // Not a timing check: a bound on how long to wait for a JVM that may hang.
        boolean ended = process.waitFor(2, TimeUnit.MINUTES);
        if (!ended) {
            process.destroyForcibly().waitFor();
        }
        String printed = Files.readString(output, StandardCharsets.UTF_8);
        assertThat(ended).as("java %s ended; it printed:%n%s", command, printed).isTrue();
        return new Run(process.exitValue(), printed);
    }
}
