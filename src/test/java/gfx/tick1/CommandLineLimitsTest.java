package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gfx.tick1.command.render.RenderCommand;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import picocli.CommandLine;

/** Every option a user types is checked before any work starts: one line, status 2. */
class CommandLineLimitsTest {

    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            --width 0               | --width 0: must be from 1 to 16384
            --width -5              | --width -5: must be from 1 to 16384
            --width 16385           | --width 16385: must be from 1 to 16384
            --height 0              | --height 0: must be from 1 to 16384
            --height 100000         | --height 100000: must be from 1 to 16384
            --width 99999999999     | Invalid value for option '--width': '99999999999' is not an int
            --width 1.5             | Invalid value for option '--width': '1.5' is not an int
            --height abc            | Invalid value for option '--height': 'abc' is not an int
            --samples 0             | --samples 0: must be from 1 to 1024
            --samples 1025          | --samples 1025: must be from 1 to 1024
            --samples lots          | Invalid value for option '--samples': 'lots' is not an int
            --threads 0             | --threads 0: must be from 1 to 256
            --threads 257           | --threads 257: must be from 1 to 256
            --threads -1            | --threads -1: must be from 1 to 256
            --threads many          | Invalid value for option '--threads': 'many' is not an int
            --no-such-option        | Unknown option: '--no-such-option'
            an-extra-argument       | Unmatched argument at index 4: 'an-extra-argument'
            """)
    void anOutOfRangeOrMalformedOptionIsRefusedInOneLine(String options, String message) {
        String[] args = (String.join(" ", "-i", "scenes/basic_scene.xml", "-o", dir.resolve("o.png").toString())
                + " " + options).split(" ");
        CliRun run = CliRun.of(args);
        assertThat(run.status()).as(run.err()).isEqualTo(RenderCommand.EXIT_USAGE);
        assertThat(run.err()).isEqualTo("tick1: " + message + " (see tick1 --help)" + System.lineSeparator());
        assertThat(dir.resolve("o.png")).doesNotExist();
    }

    @Test
    void anImageTooBigForTheHeapIsRefusedBeforeRendering() {
        // 16384 x 16384 needs 2 GiB (8 bytes a pixel); the build gives tests a 2 GiB heap, half of it usable.
        assumeTrue(Runtime.getRuntime().maxMemory() / 2 < 8L * 16384 * 16384, "a heap big enough for the image");
        CliRun run = CliRun.of("-i", "scenes/basic_scene.xml", "-o", dir.resolve("o.png").toString(),
                "--width", "16384", "--height", "16384");
        assertThat(run.status()).as(run.err()).isEqualTo(RenderCommand.EXIT_USAGE);
        assertThat(run.err()).matches("tick1: a 16384 x 16384 image needs about 2048 MiB, more than half of the "
                + "\\d+ MiB this Java may use; raise that with JAVA_OPTS=-Xmx\\.\\.\\. \\(see tick1 --help\\)\\R");
    }

    @Test
    void standardOutputThatCannotBeWrittenGivesStatusThree() {
        PrintStream closedPipe = new PrintStream(new OutputStream() {
            @Override
            public void write(int b) throws IOException {
                throw new IOException("Broken pipe");
            }
        });
        StringWriter err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new RenderCommand(closedPipe));
        commandLine.setErr(new PrintWriter(err, true));
        int status = commandLine.execute("-i", "scenes/basic_scene.xml", "-o", "-", "--width", "8", "--height", "6");
        assertThat(status).as(err.toString()).isEqualTo(RenderCommand.EXIT_CANNOT_WRITE);
        assertThat(err.toString()).isEqualTo("tick1: -: cannot write the image: standard output was closed or "
                + "could not be written" + System.lineSeparator());
    }
}
