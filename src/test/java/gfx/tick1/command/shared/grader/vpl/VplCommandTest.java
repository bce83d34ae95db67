package gfx.tick1.command.shared.grader.vpl;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code tick1 vpl}: the files it writes, and what it refuses. */
@Order(17)   // one of the longest classes: it starts early (junit-platform.properties)
class VplCommandTest {

    @TempDir
    Path dir;

    private CliRun vpl(String... options) {
        String[] args = new String[options.length + 5];
        args[0] = "vpl";
        args[1] = "--out";
        args[2] = dir.resolve("out").toString();
        args[3] = "--tick1";
        args[4] = "/opt/tick1/bin/tick1";
        System.arraycopy(options, 0, args, 5, options.length);
        return CliRun.of(args);
    }

    @Test
    void writesAnExecutableEvaluateScriptThatRunsTheTick1GivenAndAReadme() throws IOException {
        CliRun run = vpl("--max-grade", "7.5");
        Path script = dir.resolve("out").resolve(VplCommand.EVALUATE);

        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(Files.isExecutable(script)).as("vpl_evaluate.sh is executable").isTrue();
        assertThat(Files.readString(script)).as("vpl_evaluate.sh")
                .contains("TICK1='/opt/tick1/bin/tick1'", "MAX_GRADE='7.5'", "HIDDEN_SCENES=0",
                        "grade --format vpl", VplReport.NOT_SET_UP);
        assertThat(Files.readString(dir.resolve("out").resolve("README.txt"))).as("README.txt")
                .contains("Run off, Debug off", "bubblewrap", "built-in hidden scene, which is public");
    }

    @Test
    void copiesTheHiddenScenesUnderNamesThatTellNothing() throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Files.copy(Path.of("scenes", "no-ambient.xml"), scenes.resolve("the-answer-is-red.xml"));
        CliRun run = vpl("--scenes", scenes.toString());

        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(dir.resolve("out").resolve(VplCommand.HIDDEN_PREFIX + "1.xml")).as("the hidden scene")
                .hasSameTextualContentAs(scenes.resolve("the-answer-is-red.xml"));
        assertThat(Files.readString(dir.resolve("out").resolve(VplCommand.EVALUATE))).as("vpl_evaluate.sh")
                .contains("HIDDEN_SCENES=1").doesNotContain("the-answer-is-red");
    }

    @Test
    void aSceneThatCannotBeGradedWithIsOneLineAndNothingIsWritten() throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(scenes.resolve("broken.xml"), "<scene><sphere");
        CliRun run = vpl("--scenes", scenes.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(VplCommand.EXIT_USAGE);
        assertThat(run.err().lines().count()).as("one line").isEqualTo(1);
        assertThat(run.err()).as("the line names the file").contains("broken.xml");
        assertThat(dir.resolve("out")).as("nothing written").doesNotExist();
    }

    @Test
    void anEarlierActivitysFilesAreKeptUnlessForced() {
        assertThat(vpl().status()).as("the first").isZero();
        CliRun again = vpl();

        assertThat(again.status()).as(again.transcript()).isEqualTo(VplCommand.EXIT_USAGE);
        assertThat(again.err()).as("the reason").contains("--force");
        assertThat(vpl("--force").status()).as("with --force").isZero();
    }

    @Test
    void aPassGradeWithADecimalCommaIsRefused() {
        CliRun run = vpl("--max-grade", "7,5");

        assertThat(run.status()).as(run.transcript()).isEqualTo(2);
        assertThat(run.err()).as("the reason").contains("7,5");
    }

    /** An installed tick1 in {@code folder}: bin/tick1 and a jar in lib, with the modes Gradle's installDist gives. */
    private static Path installedIn(Path folder) throws IOException {
        Path launcher = Files.writeString(Files.createDirectories(folder.resolve("bin")).resolve("tick1"),
                "#!/bin/sh\n");
        Files.setPosixFilePermissions(launcher, PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.writeString(Files.createDirectories(folder.resolve("lib")).resolve("tick1.jar"), "jar");
        Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwxr-xr-x"));
        return launcher;
    }

    @Test
    void aTick1InAFolderOtherUsersCannotPassThroughIsRefusedInOneLineSayingWhatToDo() throws IOException {
        Path launcher = installedIn(dir.resolve("private").resolve("tick1"));
        Files.setPosixFilePermissions(dir.resolve("private"), PosixFilePermissions.fromString("rwx------"));
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        CliRun run = CliRun.of("vpl", "--out", dir.resolve("out").toString(), "--tick1", launcher.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(VplCommand.EXIT_USAGE);
        assertThat(run.err().lines().count()).as("one line").isEqualTo(1);
        assertThat(run.err()).as("the folder, why and what to do")
                .contains(dir.resolve("private") + " lets no other user through (mode 0700)", "VPL's user",
                        "--tick1", "chmod o+x " + dir.resolve("private"));
        assertThat(dir.resolve("out")).as("nothing written").doesNotExist();
    }

    @Test
    void aTick1WhoseLibrariesOtherUsersCannotReadIsRefusedNamingTheFile() throws IOException {
        Path launcher = installedIn(dir.resolve("tick1"));
        Path jar = dir.resolve("tick1").resolve("lib").resolve("tick1.jar");
        Files.setPosixFilePermissions(jar, PosixFilePermissions.fromString("rw-------"));
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        CliRun run = CliRun.of("vpl", "--out", dir.resolve("out").toString(), "--tick1", launcher.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(VplCommand.EXIT_USAGE);
        assertThat(run.err()).as("the file and what to do").contains(jar + " cannot be read by other users",
                "chmod o+r " + jar);
    }

    @Test
    void aTick1OtherUsersCanRunIsWritten() throws IOException {
        Path launcher = installedIn(dir.resolve("tick1"));
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        CliRun run = CliRun.of("vpl", "--out", dir.resolve("out").toString(), "--tick1", launcher.toString());

        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(Files.readString(dir.resolve("out").resolve(VplCommand.EVALUATE))).as("vpl_evaluate.sh")
                .contains("TICK1='" + launcher + "'");
    }

    @Test
    void aRelativeTick1IsRefusedAsTheJailCannotFindIt() {
        CliRun run = CliRun.of("vpl", "--out", dir.resolve("out").toString(), "--tick1", "bin/tick1");

        assertThat(run.status()).as(run.transcript()).isEqualTo(2);
        assertThat(run.err()).as("the reason").contains("absolute path");
    }
}
