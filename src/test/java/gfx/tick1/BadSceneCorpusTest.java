package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.engine.image.EarlierImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.parallel.Isolated;

/**
 * Every file of the bad-input corpus (src/test/resources/bad-scenes), run through the real command
 * line: status 1, exactly the line that EXPECTED.txt gives on standard error and nothing else, no
 * stack trace, and an existing output file left byte for byte as it was with no temporary file
 * beside it.
 */
@Isolated("one test sets the default locale, by which the whole program formats numbers and the JDK words errors")
class BadSceneCorpusTest {

    static final Path CORPUS = Path.of("src/test/resources/bad-scenes");
    private static final Path EXPECTED = CORPUS.resolve("EXPECTED.txt");

    /** One line of EXPECTED.txt: a file, the options to run it with, and the error it must give. */
    record Case(String file, List<String> options, String error) {
        @Override
        public String toString() {
            return file + (options.isEmpty() ? "" : " " + String.join(" ", options));
        }
    }

    static List<Case> cases() throws IOException {
        List<Case> cases = new ArrayList<>();
        for (String line : Files.readAllLines(EXPECTED, StandardCharsets.UTF_8)) {
            if (line.isBlank() || line.startsWith("#")) {
                continue;
            }
            String[] fields = line.split(" \\| ", 3);
            assertThat(fields).as("EXPECTED.txt line: %s", line).hasSize(3);
            List<String> options = fields[1].isBlank() ? List.of() : List.of(fields[1].strip().split(" "));
            cases.add(new Case(fields[0].strip(), options, fields[2]));
        }
        return cases;
    }

    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void eachBadFileGivesItsOneLineErrorAndLeavesTheOldImage(Case c) throws IOException {
        Path output = EarlierImage.writeTo(dir.resolve("out.png"));
        String input = CORPUS.resolve(c.file()).toString();
        List<String> args = new ArrayList<>(c.options());
        args.addAll(List.of("-i", input, "-o", output.toString(), "--width", "16", "--height", "12"));

        CliRun run = CliRun.of(args.toArray(String[]::new));

        assertThat(run.status()).as(run.err()).isEqualTo(RenderCommand.EXIT_BAD_SCENE);
        assertThat(run.err()).as("standard error").isEqualTo("tick1: " + CORPUS + "/" + c.error()
                + System.lineSeparator());
        assertThat(run.err()).as("no stack trace").doesNotContain("\tat ", "Exception");
        assertThat(run.out()).as("standard output").isEmpty();
        assertThat(Files.readAllBytes(output)).as("the earlier image").isEqualTo(EarlierImage.bytes());
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files).as("files beside the output").containsExactly(output);
        }
    }

    @Test
    void theParsersMessagesAreTheSameWhateverTheMachinesLanguage() throws IOException {
        Case unquoted = cases().stream().filter(c -> c.file().equals("unquoted-attribute.xml"))
                .findFirst().orElseThrow();
        Locale before = Locale.getDefault();
        Locale.setDefault(Locale.GERMANY); // the JDK's parser has German messages
        try {
            eachBadFileGivesItsOneLineErrorAndLeavesTheOldImage(unquoted);
        } finally {
            Locale.setDefault(before);
        }
    }

    @Test
    void theCorpusHasAtLeastSixtyFilesAndEveryOneHasAnExpectedLine() throws IOException {
        Set<String> listed = cases().stream().map(Case::file).collect(Collectors.toCollection(TreeSet::new));
        Set<String> present;
        try (Stream<Path> files = Files.list(CORPUS)) {
            present = files.map(p -> p.getFileName().toString()).filter(name -> !name.equals("EXPECTED.txt"))
                    .collect(Collectors.toCollection(TreeSet::new));
        }
        assertThat(present).as("files in %s", CORPUS).hasSizeGreaterThanOrEqualTo(60);
        assertThat(listed).as("files named in EXPECTED.txt").isEqualTo(present);
    }
}
