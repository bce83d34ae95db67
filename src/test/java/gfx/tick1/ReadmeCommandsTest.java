package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;

import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import gfx.tick1.command.shared.cli.MainClass;
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
import java.util.jar.Attributes;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The commands a newcomer copies from the README and CONTRIBUTING.md: every {@code tick1} and
 * {@code java -jar tick1.jar} line of their code blocks is a command line tick1 accepts, and every
 * {@code gradle} line names a task the build has; and the section for students runs, as written, in
 * the starter kit's folder with the students' jar there.
 */
@Order(12)   // one of the longest classes: it starts early (junit-platform.properties)
class ReadmeCommandsTest {

    private static final List<Path> PAGES = List.of(Path.of("README.md"), Path.of("CONTRIBUTING.md"));
    /** Tasks Gradle's java and application plugins make, which build.gradle does not name. */
    private static final Set<String> PLUGIN_TASKS = Set.of("test", "check", "installDist", "build",
            "compileJava");
    /** How a line runs tick1: the installed launcher, or the students' jar. */
    private static final Pattern TICK1 = Pattern.compile("^(?:tick1|java -jar tick1\\.jar) ");

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
        return commandLines().stream().filter(line -> TICK1.matcher(line).find());
    }

    static Stream<String> gradleCommands() throws IOException {
        return commandLines().stream().filter(line -> line.startsWith("gradle "));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("tick1Commands")
    void everyTick1CommandShownIsACommandLineTick1Accepts(String command) {
        String[] args = TICK1.matcher(command).replaceFirst("").strip().split("\\s+");
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
     * solution) with {@code tick1.jar} put in it, a jar that runs this build, line by line in a
     * shell. Every line succeeds; none finds a file missing.
     */
    @Test
    void theStudentSectionWorksAsWrittenInsideTheStarterKit(@TempDir Path dir) throws Exception {
        assertThat(CliRun.of("starter", "--out", dir.resolve("kit").toString()).status()).isZero();
        Path kit = dir.resolve("kit");
        for (String name : List.of("Sphere.java", "Renderer.java")) {
            Files.copy(Path.of("src/test/resources/students/correct", name), kit.resolve("src/gfx/tick1/" + name),
                    StandardCopyOption.REPLACE_EXISTING);
        }
        writeJarOfThisBuild(kit.resolve("tick1.jar"));
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> lines = studentCommands();
        assertThat(lines).as("the section's commands").hasSizeGreaterThan(3)
                .anySatisfy(line -> assertThat(line).startsWith("java -jar tick1.jar "));
        for (String written : lines) {
            // Where no sandbox can be made, a student gives grade --no-sandbox, as the section says.
            String line = !SandboxNeeded.available() && written.startsWith("java -jar tick1.jar grade ")
                    ? written + " --no-sandbox" : written;
            ProcessBuilder shell = new ProcessBuilder("sh", "-c", line).directory(kit.toFile())
                    .redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
            shell.environment().put("PATH", Path.of(java).getParent() + File.pathSeparator + System.getenv("PATH"));
            // The tests' JVMs start with the options that make a short run cheapest (CliRun.java).
            List<String> jvm = CliRun.java();
            shell.environment().put("JDK_JAVA_OPTIONS", String.join(" ", jvm.subList(1, jvm.size())));
            Process process = shell.start();
            String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(process.waitFor()).as("%s in the kit's folder:%n%s", line, output).isZero();
            assertThat(output).as(line).doesNotContainIgnoringCase("no such file");
        }
    }

    /**
     * A jar that {@code java -jar} runs as tick1: its manifest names tick1's main class and, as its
     * class path, this build's classes and libraries (the students' jar holds them; this one points
     * at them, so the test needs no build of that jar).
     */
    private static void writeJarOfThisBuild(Path jar) throws IOException {
        Manifest manifest = new Manifest();
        manifest.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        manifest.getMainAttributes().put(Attributes.Name.MAIN_CLASS, MainClass.NAME);
        manifest.getMainAttributes().put(Attributes.Name.CLASS_PATH,
                Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator))
                        .map(entry -> Path.of(entry).toUri().toString()).collect(Collectors.joining(" ")));
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar), manifest)) {
            out.flush();
        }
    }

    /**
     * The section for students sends them to work in the starter kit's folder: a scene its prose names for
     * {@code tick1 preview} is one the kit holds there, not a file of this repository.
     */
    @Test
    void theStudentSectionPreviewsASceneOfTheStarterKit(@TempDir Path dir) throws Exception {
        assertThat(CliRun.of("starter", "--out", dir.resolve("kit").toString()).status()).isZero();
        String readme = Files.readString(Path.of("README.md"));
        String section = readme.substring(readme.indexOf("## For students"), readme.indexOf("## For course staff"));
        Matcher preview = Pattern.compile("`(?:tick1|java -jar tick1\\.jar) preview ([^`]+)`").matcher(section);
        assertThat(preview.find()).as("the section for students shows tick1 preview").isTrue();
        assertThat(dir.resolve("kit").resolve(preview.group(1))).as("the scene it previews, in the kit's folder")
                .isRegularFile();
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

    /** The lines of the first code block of the README's section "Build and render": its set-up. */
    static List<String> setUpCommands() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        String section = readme.substring(readme.indexOf("## Build and render"));
        String block = section.substring(section.indexOf("```sh\n") + "```sh\n".length());
        return block.substring(0, block.indexOf("```")).lines().filter(line -> !line.isBlank()).toList();
    }

    /**
     * The set-up is two commands for a fresh Debian or Ubuntu: the first fetches the package lists (a new
     * machine has none) and installs the JDK, Gradle and bubblewrap (which grade and diff's checks need).
     */
    @Test
    void theSetUpIsOneCommandThatInstallsEverythingAndOneThatBuildsAndRenders() throws IOException {
        List<String> setUp = setUpCommands();
        assertThat(setUp).as("the set-up's commands").hasSize(2);
        assertThat(setUp.get(0)).as("the install command").startsWith("apt-get update && apt-get install -y ")
                .contains(" openjdk-17-jdk", " gradle", " bubblewrap");
        assertThat(setUp.get(1)).as("the build command").startsWith("gradle --no-daemon installDist && ")
                .contains("build/install/tick1/bin/tick1 ");
    }

    /** .ci/run, which CI runs on a clean clone, runs the README's set-up as the README writes it. */
    @Test
    void ciRunsTheReadmesSetUpAsWritten() throws Exception {
        Process ci = new ProcessBuilder("bash", ".ci/run", "--show-setup").redirectErrorStream(true).start();
        String shown = new String(ci.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(ci.waitFor()).as(shown).isZero();

        assertThat(shown.lines().toList()).as("the commands .ci/run runs").isEqualTo(setUpCommands());
    }

    /**
     * The README's line that puts tick1 on the PATH, run once in the project's folder, gives {@code tick1} in a new
     * terminal (a new interactive bash, which reads ~/.bashrc) in another folder: the starter kit's, say.
     */
    @Test
    void thePathLineGivesTick1InANewTerminalInAnyFolder(@TempDir Path dir) throws Exception {
        String line = commandLines().stream().filter(command -> command.contains(">> ~/.bashrc")).findFirst()
                .orElseThrow(() -> new AssertionError("the README has no line that adds tick1 to ~/.bashrc"));
        Path project = dir.resolve("my projects/tick1 build");
        Path bin = Files.createDirectories(project.resolve("build/install/tick1/bin"));
        Files.writeString(bin.resolve("tick1"), "#!/bin/sh\necho \"the installed tick1, in $PWD\"\n");
        assertThat(bin.resolve("tick1").toFile().setExecutable(true)).isTrue();
        Path home = Files.createDirectories(dir.resolve("home"));
        Path kit = Files.createDirectories(dir.resolve("kit"));
        assertThat(shell(project, home, "bash", "-c", line).status()).isZero();

        Shell newTerminal = shell(kit, home, "bash", "-i", "-c", "tick1");

        assertThat(newTerminal.status()).as(newTerminal.output()).isZero();
        assertThat(newTerminal.output()).as("a new terminal in the kit's folder")
                .contains("the installed tick1, in " + kit);
    }

    private record Shell(int status, String output) {
    }

    /** Runs {@code command} in {@code folder} with {@code home} as HOME and the system's own PATH. */
    private static Shell shell(Path folder, Path home, String... command) throws Exception {
        ProcessBuilder builder = new ProcessBuilder(command).directory(folder.toFile()).redirectErrorStream(true)
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        builder.environment().put("HOME", home.toString());
        builder.environment().put("PATH", "/usr/local/bin:/usr/bin:/bin");
        Process process = builder.start();
        String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        return new Shell(process.waitFor(), output);
    }

    /** The README's test command: the code block of the staff's section that runs {@code gradle ... check}. */
    @Test
    void ciRunsTheReadmesTestCommand() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        String staff = readme.substring(readme.indexOf("## For course staff"));
        String command = staff.lines().filter(line -> line.startsWith("gradle ") && line.endsWith(" check"))
                .findFirst().orElseThrow(() -> new AssertionError("the staff's section shows no test command"));
        String ci = Files.readString(Path.of(".ci/run"));

        assertThat(ci).as(".ci/run's test command").contains("TEST_CMD=(" + command + ")");
    }
}
