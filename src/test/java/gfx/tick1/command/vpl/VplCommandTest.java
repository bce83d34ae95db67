package gfx.tick1.command.vpl;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.grader.sandbox.SandboxProperties;
import gfx.tick1.command.shared.grader.vpl.VplReport;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code tick1 vpl}: the files it writes, and what it refuses. */
@SandboxProperties.Read
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

    @Test
    void aRelativeTick1IsRefusedAsTheJailCannotFindIt() {
        CliRun run = CliRun.of("vpl", "--out", dir.resolve("out").toString(), "--tick1", "bin/tick1");

        assertThat(run.status()).as(run.transcript()).isEqualTo(2);
        assertThat(run.err()).as("the reason").contains("absolute path");
    }
}
