package gfx.tick1.command.diff;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.javacode.Nesting;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code tick1 diff} on a file it cannot compare: one line that says where the file goes wrong, as
 * file:line:column with the column an editor's cursor shows there (a tab is one character, as it is
 * one step of the cursor), and exit status 2.
 */
class DiffFileErrorsTest {

    @TempDir
    Path dir;

    @Test
    void aParseErrorPointsAtTheTokenTheParserFoundNotTheOneBeforeIt() throws IOException {
        Path sphere = write("class Sphere {\n    double r = ;\n}\n");

        CliRun run = CliRun.of("diff", sphere.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).as(run.transcript()).startsWith("tick1 diff: " + sphere + ":2:16: ");
    }

    @Test
    void aTabBeforeAParseErrorCountsAsOneColumn() throws IOException {
        Path sphere = write("class Sphere {\n\tdouble r = ;\n}\n");

        CliRun run = CliRun.of("diff", sphere.toString());

        assertThat(run.err()).as(run.transcript()).startsWith("tick1 diff: " + sphere + ":2:13: ");
    }

    @Test
    void aStringLeftOpenIsPlacedAsFileLineColumn() throws IOException {
        Path sphere = write("class Sphere {\n  String s = \"abc;\n}\n");

        CliRun run = CliRun.of("diff", sphere.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err().lines()).as(run.transcript()).singleElement().asString()
                .startsWith("tick1 diff: " + sphere + ":2:");
    }

    @Test
    void aFileThatIsNotUtf8IsPlacedAtItsFirstBadByte() throws IOException {
        Path sphere = dir.resolve("Sphere.java");
        Files.write(sphere, "class Sphere {\n    String s = \"caf\u00e9\";\n}\n".getBytes(StandardCharsets.ISO_8859_1));

        CliRun run = CliRun.of("diff", sphere.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).as(run.transcript())
                .isEqualTo("tick1 diff: " + sphere + ":2:20: not UTF-8 text: byte 0xE9 is not part of a UTF-8 "
                        + "character; save the file as UTF-8\n");
    }

    @Test
    void aDeviceThatNeverEndsIsReadOnlyUpToABoundAndRefusedInOneLine() throws Exception {
        Path zero = Path.of("/dev/zero");
        assumeTrue(Files.isReadable(zero), "needs /dev/zero");

        CliRun run = CliRun.inJvm(dir, List.of("-Xmx256m"), "diff", zero.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).as(run.transcript()).isEqualTo("tick1 diff: /dev/zero: larger than 1 MiB, far more "
                + "than any Sphere.java or Renderer.java\n");
    }

    /**
     * Blocks nested thousands deep, in a Java of small heap: their text would grow as the square of the depth. The
     * line places where the nesting passes the bound: the block one deeper than it.
     */
    @Test
    void codeNestedDeeperThanAnySolutionIsRefusedInOneLine() throws Exception {
        int depth = 3_500;
        Path sphere = write("class Sphere {\n    void deep() " + "{".repeat(depth) + "}".repeat(depth) + "\n}\n");

        CliRun run = CliRun.inJvm(dir, List.of("-Xmx160m"), "diff", "--no-sandbox", sphere.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).as(run.transcript()).isEqualTo("tick1 diff: " + sphere + ":2:"
                + ("    void deep() ".length() + Nesting.MOST_DEPTH + 1) + ": deep(): blocks, statements and "
                + "expressions nested more than " + Nesting.MOST_DEPTH + " deep: too deeply nested to compare\n");
    }

    private Path write(String text) throws IOException {
        return Files.writeString(dir.resolve("Sphere.java"), text);
    }
}
