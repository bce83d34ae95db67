package gfx.tick1.command.render;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.Tick1;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;

/**
 * The guess at a plain render's options, made before picocli reads the command line: wherever it
 * guesses, it guesses what picocli reads; anything else it leaves to picocli.
 */
class CommandLineGuessTest {

    private static final String SCENE = "scenes/tick1.xml";

    static List<String> commandLines() {
        return List.of("-i " + SCENE + " -o out.png", "--input " + SCENE + " --output=out.png -q",
                "-i " + SCENE + " --width 320 --height=200 --samples 4 --threads 1",
                "-i " + SCENE + " --intersection HANDOUT --strict --timings", "--input=" + SCENE + " -o -",
                "-i " + SCENE + " --width 0x40", "-i " + SCENE + " --width 007", "-i " + SCENE + " --width=+7",
                "-i " + SCENE + " -o -q", "-i " + SCENE + " -i " + SCENE, "-qi " + SCENE,
                "-i " + SCENE + " --intersection stable", "-i " + SCENE + " --intersection nonsense",
                "-i scenes", "-i " + SCENE + " --samples 2000", "-o x.png", "-i " + SCENE + " --threads 0");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("commandLines")
    void aGuessIsWhatPicocliReadsOrNone(String line) {
        String[] args = line.split(" ");
        Optional<RenderOptions> guess = CommandLineGuess.of(args);
        if (guess.isEmpty()) {
            return;
        }
        RenderCommand command = new RenderCommand();
        CommandLine commandLine = Tick1.commandLine(command, args);
        commandLine.parseArgs(args);
        assertThat(guess).as(line).contains(command.options());
    }

    @ParameterizedTest
    @ValueSource(strings = {"-i " + SCENE + " -o out.png", "-i " + SCENE + " --width 320 --strict -q"})
    void thePlainFormsAreGuessed(String line) {
        assertThat(CommandLineGuess.of(line.split(" "))).as(line).isPresent();
    }

    @ParameterizedTest
    @ValueSource(strings = {"-qi " + SCENE, "-i " + SCENE + " -i " + SCENE, "-i " + SCENE + " --width",
        "-i " + SCENE + " --width ten", "-i " + SCENE + " -o -q", "-i " + SCENE + " --help", "grade -i " + SCENE,
        "-i /dev/stdin", "-i scenes", "-i no-such-scene.xml"})
    void anythingElseIsLeftToPicocli(String line) {
        assertThat(CommandLineGuess.of(line.split(" "))).as(line).isEmpty();
    }
}
