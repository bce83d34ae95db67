package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.render.CommandLineGuess;
import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.command.render.RenderJob;
import gfx.tick1.command.render.RenderOptions;
import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * A render started on a guess at the command line, before picocli has read it: used when picocli
 * reads the same options, thrown away when it does not, and either way the run prints and writes
 * exactly what a run without the guess does.
 */
class RenderAheadTest {

    private static CliRun run(RenderJob ahead, String... args) {
        ByteArrayOutputStream binary = new ByteArrayOutputStream();
        StringWriter out = new StringWriter(), err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new RenderCommand(binary, ahead), args);
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        int status = commandLine.execute(args);
        return new CliRun(status, out.toString(), err.toString(), binary.toByteArray());
    }

    private static void assertSameRun(CliRun expected, CliRun actual) {
        assertThat(actual.status()).as(actual.transcript()).isEqualTo(expected.status());
        assertThat(actual.out()).isEqualTo(expected.out());
        assertThat(actual.err()).isEqualTo(expected.err());
        assertThat(actual.stdout()).as("the PNG's bytes").isEqualTo(expected.stdout());
    }

    @Test
    void aRightGuessGivesTheSameImageAndMessages() {
        String[] args = {"-i", "scenes/tick1.xml", "-o", "-", "--width", "160", "--height", "120", "--samples", "3"};
        RenderJob ahead = RenderJob.start(CommandLineGuess.of(args).orElseThrow());
        assertSameRun(CliRun.of(args), run(ahead, args));
    }

    @Test
    void aWrongGuessIsThrownAwayForWhatPicocliRead() {
        String[] args = {"-i", "scenes/tick1.xml", "-o", "-", "--width", "160", "--height", "120"};
        RenderOptions wrong = new RenderOptions("scenes/tick1.xml", false, 200, 120, 1,
                CommandLineGuess.of(args).orElseThrow().intersection(), null);
        assertSameRun(CliRun.of(args), run(RenderJob.start(wrong), args));
    }

    @Test
    void aGuessAtAnInvalidCommandLineChangesNoMessage() {
        String[] args = {"-i", "scenes/tick1.xml", "-o", "-", "--width", "0"};
        RenderOptions guess = new RenderOptions("scenes/tick1.xml", false, 640, 480, 1,
                CommandLineGuess.of("-i", "scenes/tick1.xml").orElseThrow().intersection(), null);
        assertSameRun(CliRun.of(args), run(RenderJob.start(guess), args));
    }

    @Test
    void aSceneErrorFoundAheadIsReportedAsWithoutTheGuess() {
        String[] args = {"-i", "src/test/resources/bad-scenes/binary-garbage.xml", "-o", "-"};
        Optional<RenderOptions> guess = CommandLineGuess.of(args);
        assertThat(guess).as("the guess at a plain render's command line").isPresent();
        assertSameRun(CliRun.of(args), run(RenderJob.start(guess.orElseThrow()), args));
    }
}
