package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The commands a newcomer copies from the README and CONTRIBUTING.md: every {@code tick1} line of
 * their code blocks is a command line tick1 accepts, and every {@code gradle} line names a task the
 * build has. (Whether each then succeeds depends on the reader's files; what it does is tested
 * elsewhere.)
 */
class ReadmeCommandsTest {

    private static final List<Path> PAGES = List.of(Path.of("README.md"), Path.of("CONTRIBUTING.md"));
    /** Tasks Gradle's java and application plugins make, which build.gradle does not name. */
    private static final Set<String> PLUGIN_TASKS = Set.of("test", "check", "installDist", "build",
            "compileJava");

    /** The lines of the pages' fenced code blocks, without a trailing {@code # comment}. */
    static List<String> commandLines() throws IOException {
        List<String> lines = new ArrayList<>();
        for (Path page : PAGES) {
            boolean inBlock = false;
            for (String line : Files.readAllLines(page)) {
                if (line.startsWith("```")) {
                    inBlock = !inBlock;
                } else if (inBlock) {
                    lines.add(line.replaceFirst("\\s+#.*$", "").strip());
                }
            }
        }
        return lines;
    }

    static Stream<String> tick1Commands() throws IOException {
        return commandLines().stream().filter(line -> line.startsWith("tick1 "));
    }

    static Stream<String> gradleCommands() throws IOException {
        return commandLines().stream().filter(line -> line.startsWith("gradle "));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("tick1Commands")
    void everyTick1CommandShownIsACommandLineTick1Accepts(String command) {
        String[] args = Arrays.stream(command.split("\\s+")).skip(1).toArray(String[]::new);
        assertThatCode(() -> Tick1.commandLine(new RenderCommand()).parseArgs(args)).as(command)
                .doesNotThrowAnyException();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("gradleCommands")
    void everyGradleCommandShownNamesATaskOfTheBuild(String command) throws IOException {
        String build = Files.readString(Path.of("build.gradle"));
        String task = Arrays.stream(command.split("\\s+")).skip(1).filter(word -> !word.startsWith("-"))
                .findFirst().orElse("");
        assertThat(PLUGIN_TASKS.contains(task) || build.contains("registerTask('" + task + "'"))
                .as("%s: task %s", command, task).isTrue();
    }

    @Test
    void ciRunsTheReadmesTestCommand() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        String command = readme.substring(readme.indexOf("## Test")).split("```sh\n", 2)[1].split("\n", 2)[0];
        String ci = Files.readString(Path.of(".ci/run"));

        assertThat(ci).as(".ci/run's test command").contains("TEST_CMD=(" + command + ")");
    }
}
