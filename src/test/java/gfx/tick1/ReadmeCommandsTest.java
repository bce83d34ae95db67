package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;

import gfx.tick1.cli.MainClass;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The commands a newcomer copies from the README and CONTRIBUTING.md: every {@code tick1} line of
 * their code blocks is a command line tick1 accepts, and every {@code gradle} line names a task the
 * build has; and the section for students runs, as written, in the starter kit's folder.
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

    /** The lines of the first code block of the README's section for students. */
    static List<String> studentCommands() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        String section = readme.substring(readme.indexOf("## For students"));
        String block = section.substring(section.indexOf("```sh\n") + "```sh\n".length());
        return block.substring(0, block.indexOf("```")).lines().map(String::strip).filter(line -> !line.isEmpty())
                .toList();
    }

    /**
     * The student section as a student runs it: in a fresh starter kit (holding a correct
     * solution), line by line in a shell whose {@code tick1} is this build. Every line succeeds;
     * none finds a file missing.
     */
    @Test
    void theStudentSectionWorksAsWrittenInsideTheStarterKit(@TempDir Path dir) throws Exception {
        assertThat(CliRun.inFolder(dir, "starter", "--out", "kit").status()).isZero();
        Path kit = dir.resolve("kit");
        for (String name : List.of("Sphere.java", "Renderer.java")) {
            Files.copy(Path.of("src/test/resources/students/correct", name), kit.resolve("src/gfx/tick1/" + name),
                    StandardCopyOption.REPLACE_EXISTING);
        }
        Path bin = Files.createDirectories(dir.resolve("bin"));
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Files.writeString(bin.resolve("tick1"), "#!/bin/sh\nexec '" + java + "' -cp '"
                + System.getProperty("java.class.path") + "' " + MainClass.NAME + " \"$@\"\n");
        assertThat(bin.resolve("tick1").toFile().setExecutable(true)).isTrue();
        List<String> lines = studentCommands();
        assertThat(lines).as("the section's commands").hasSizeGreaterThan(3);
        for (String line : lines) {
            ProcessBuilder shell = new ProcessBuilder("sh", "-c", line).directory(kit.toFile())
                    .redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
            shell.environment().put("PATH", bin + File.pathSeparator + Path.of(java).getParent() + File.pathSeparator
                    + System.getenv("PATH"));
            Process process = shell.start();
            String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(process.waitFor()).as("%s in the kit's folder:%n%s", line, output).isZero();
            assertThat(output).as(line).doesNotContainIgnoringCase("no such file");
        }
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
