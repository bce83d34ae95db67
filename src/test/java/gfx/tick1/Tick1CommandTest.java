package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.engine.image.EarlierImage;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The real entry point, run as {@code main} runs it, with what it printed captured. */
class Tick1CommandTest {

    @TempDir
    Path dir;

    private Path existingOutput() throws IOException {
        return EarlierImage.writeTo(dir.resolve("out.png"));
    }

    private Path scene(String xml) throws IOException {
        Path scene = dir.resolve("scene.xml");
        Files.writeString(scene, xml);
        return scene;
    }

    @Test
    void rendersTheSceneToAPngOfTheDefaultSize() throws IOException {
        Path output = dir.resolve("out.png");
        CliRun run = CliRun.of("--input", "scenes/tick1.xml", "--output", output.toString());
        assertThat(run.status()).as(run.err()).isZero();
        assertThat(run.err()).isEmpty();
        BufferedImage image = ImageIO.read(output.toFile());
        assertThat(image.getWidth()).isEqualTo(640);
        assertThat(image.getHeight()).isEqualTo(480);
    }

    @Test
    void shortOptionsAndSizeOptionsWork() throws IOException {
        Path output = dir.resolve("small.png");
        CliRun run = CliRun.of("-i", "scenes/basic_scene.xml", "-o", output.toString(),
                "--width", "32", "--height", "20");
        assertThat(run.status()).as(run.err()).isZero();
        assertThat(ImageIO.read(output.toFile()).getWidth()).isEqualTo(32);
    }

    @Test
    void quietPrintsNothingOnSuccess() {
        CliRun run = CliRun.of("-q", "-i", "scenes/tick1.xml", "-o", dir.resolve("q.png").toString());
        assertThat(run.status()).isZero();
        assertThat(run.out()).isEmpty();
        assertThat(run.err()).isEmpty();
    }

    @Test
    void outputDashWritesThePngToStandardOutput() throws IOException {
        CliRun run = CliRun.of("-i", "scenes/basic_scene.xml", "-o", "-", "--width", "16", "--height", "12");
        assertThat(run.status()).isZero();
        assertThat(run.out()).as("no text may mix with the PNG bytes").isEmpty();
        assertThat(ImageIO.read(new ByteArrayInputStream(run.stdout())).getHeight()).isEqualTo(12);
    }

    @Test
    void theImageIsTheSameWhateverTheNumberOfThreads() throws IOException {
        Path one = dir.resolve("one.png"), many = dir.resolve("many.png");
        CliRun.of("-i", "scenes/hundred-spheres.xml", "-o", one.toString(), "--threads", "1");
        CliRun.of("-i", "scenes/hundred-spheres.xml", "-o", many.toString(), "--threads", "7");
        BufferedImage a = ImageIO.read(one.toFile()), b = ImageIO.read(many.toFile());
        assertThat(a.getRGB(0, 0, 640, 480, null, 0, 640)).isEqualTo(b.getRGB(0, 0, 640, 480, null, 0, 640));
    }

    @Test
    void helpAndVersionExitZero() {
        assertThat(CliRun.of("--help").out()).contains("--input", "--output", "--width", "--height", "Exit status");
        CliRun version = CliRun.of("--version");
        assertThat(version.status()).isZero();
        assertThat(version.out()).startsWith("tick1 ");
    }

    @Test
    void withoutOutputItWritesOutputPngInTheCurrentFolder() throws IOException, InterruptedException {
        Files.copy(Path.of("scenes/basic_scene.xml"), dir.resolve("basic_scene.xml"));
        CliRun run = CliRun.inFolder(dir, "--width", "16", "--height", "12");
        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(ImageIO.read(dir.resolve("output.png").toFile()).getWidth()).isEqualTo(16);
    }

    @Test
    void withoutOutputAnExistingOutputPngIsNeverReplaced() throws IOException, InterruptedException {
        // output.png is what the handout's own program writes: in a student's folder, their render.
        Files.copy(Path.of("scenes/basic_scene.xml"), dir.resolve("basic_scene.xml"));
        Path theirs = EarlierImage.writeTo(dir.resolve("output.png"));
        CliRun run = CliRun.inFolder(dir, "--width", "16", "--height", "12");
        assertThat(run.status()).as(run.transcript()).isEqualTo(RenderCommand.EXIT_USAGE);
        assertThat(run.err()).as("one line with the way out").isEqualTo("tick1: output.png already exists (it may "
                + "be your own render) and -o was not given; -o output.png replaces it, -o OTHER.png writes another"
                + System.lineSeparator());
        assertThat(theirs).as("the student's image").hasBinaryContent(EarlierImage.bytes());
        assertThat(CliRun.inFolder(dir, "-o", "output.png", "--width", "16", "--height", "12").status())
                .as("named, it is replaced").isZero();
        assertThat(ImageIO.read(theirs.toFile()).getWidth()).isEqualTo(16);
    }

    @Test
    void anOutputNamedAsAnotherImageFormatIsRefusedWithThePngName() throws IOException {
        Path jpeg = dir.resolve("out.JPG");
        CliRun run = CliRun.of("-i", "scenes/basic_scene.xml", "-o", jpeg.toString(), "--width", "8", "--height", "6");
        assertThat(run.status()).as(run.transcript()).isEqualTo(RenderCommand.EXIT_USAGE);
        assertThat(run.err()).isEqualTo("tick1: --output " + jpeg + ": tick1 writes PNG images only (every pixel "
                + "exact); name it " + dir.resolve("out.png") + " (see tick1 --help)" + System.lineSeparator());
        assertThat(jpeg).doesNotExist();
        assertThat(CliRun.of("-i", "scenes/basic_scene.xml", "-o", dir.resolve("out.tmp").toString(), "--width", "8",
                "--height", "6").status()).as("a name of no image format is the user's choice").isZero();
    }

    @Test
    void aMissingInputIsNamed() throws IOException {
        Path output = existingOutput();
        CliRun run = CliRun.of("-i", dir.resolve("missing.xml").toString(), "-o", output.toString());
        assertThat(run.status()).isEqualTo(RenderCommand.EXIT_BAD_SCENE);
        assertThat(run.err().strip()).isEqualTo("tick1: " + dir.resolve("missing.xml") + ": no such file");
        assertThat(output).hasBinaryContent(EarlierImage.bytes());
    }

    @Test
    void aWordStartingWithAnAtSignIsANameNotAFileOfArguments() throws IOException {
        // picocli reads "@NAME" as a file of further arguments unless told not to; a folder so
        // named then gave a stack trace.
        Path folder = Files.createDirectory(dir.resolve("cohort"));
        CliRun run = CliRun.of("compare", "@" + folder, dir.resolve("b.png").toString());
        assertThat(run.err()).as("one line, about the file as named").hasLineCount(1).contains("@" + folder)
                .doesNotContain("Exception");
        assertThat(run.status()).as(run.err()).isNotZero();
    }

    @Test
    void anUnwritableOutputGivesStatusThreeAndLeavesNoTemporaryFile() throws IOException {
        Path output = dir.resolve("no-such-dir").resolve("out.png");
        CliRun run = CliRun.of("-i", "scenes/basic_scene.xml", "-o", output.toString(),
                "--width", "8", "--height", "8");
        assertThat(run.status()).isEqualTo(RenderCommand.EXIT_CANNOT_WRITE);
        assertThat(run.err()).startsWith("tick1: " + output + ": cannot write the image: ").doesNotContain("\tat ");
        assertThat(run.err().lines()).hasSize(1);
    }

    @Test
    void aSuccessfulRunReplacesTheOldImageAndLeavesNoTemporaryFiles() throws IOException {
        Path output = existingOutput();
        assertThat(CliRun.of("-i", "scenes/basic_scene.xml", "-o", output.toString()).status()).isZero();
        assertThat(ImageIO.read(output.toFile())).isNotNull();
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files).containsExactly(output);
        }
    }

    @Test
    void outputThatIsADirectoryIsRefused() throws IOException {
        CliRun run = CliRun.of("-i", "scenes/basic_scene.xml", "-o", dir.toString(), "--width", "8", "--height", "8");
        assertThat(run.status()).isEqualTo(RenderCommand.EXIT_CANNOT_WRITE);
        assertThat(run.err().strip()).isEqualTo("tick1: " + dir
                + ": cannot write the image: is a directory, expected a file name for the PNG");
    }

    @Test
    void warningsArePrintedButTheImageIsStillWritten() throws IOException {
        Path scene = scene("<scene>\n<point-light colour='#FFFFFF'/>\n<point-light colour='#FFFFFF'/>\n</scene>");
        Path output = dir.resolve("w.png");
        CliRun run = CliRun.of("-i", scene.toString(), "-o", output.toString());
        assertThat(run.status()).isZero();
        assertThat(run.err()).startsWith(scene + ":3:1: warning: another <point-light>");
        assertThat(output).exists();
    }

    @Test
    void strictRefusesWhatWouldOtherwiseBeAWarning() throws IOException {
        Path scene = scene("<scene><point-light colour='#FFFFFF'/><point-light colour='#FFFFFF'/></scene>");
        CliRun run = CliRun.of("--strict", "-i", scene.toString(), "-o", dir.resolve("s.png").toString());
        assertThat(run.status()).isEqualTo(RenderCommand.EXIT_BAD_SCENE);
        assertThat(run.err()).endsWith("(an error under --strict)" + System.lineSeparator());
        assertThat(dir.resolve("s.png")).doesNotExist();
    }

    @Test
    void aPlainRenderIsParsedWithoutBuildingTheSubcommandsButAnythingElseGetsThemAll() {
        assertThat(Tick1.commandLine(new RenderCommand(), "-q", "-i", "scenes/tick1.xml", "-o", "out.png")
                .getSubcommands())
                .as("options only: no subcommand can be reached").isEmpty();
        assertThat(Tick1.commandLine(new RenderCommand(), "-o", "compare").getSubcommands())
                .as("an argument that names a subcommand").containsKeys("compare", "bench");
        assertThat(Tick1.commandLine(new RenderCommand(), "--help").getSubcommands()).as("help lists them")
                .containsKeys("compare", "diagnose", "grade", "starter", "bench", "preview");
        assertThat(Tick1.commandLine(new RenderCommand(), "comapre").getSubcommands())
                .as("a misspelt one gets suggestions")
                .isNotEmpty();
        assertThat(Tick1.commandLine(new RenderCommand(), "-qh").getSubcommands()).as("help in a cluster of flags")
                .isNotEmpty();
    }
}
