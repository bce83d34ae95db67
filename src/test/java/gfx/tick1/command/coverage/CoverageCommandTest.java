package gfx.tick1.command.coverage;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.coverage.CatalogueOnScenes;
import gfx.tick1.command.shared.coverage.Coverage;
import gfx.tick1.command.shared.coverage.GradingScenes;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code tick1 coverage} through the real entry point: its table, CSV and page, and the catalogue's
 * column in the docs.
 */
@Order(15)   // one of the longest classes: it starts early (junit-platform.properties)
class CoverageCommandTest {

    private static final String[] SMALL = {"--width", "160", "--height", "120"};

    @TempDir
    Path dir;

    @Test
    void theCsvHasOneRowPerMistakeOrPairAndScene() throws IOException {
        Path csv = dir.resolve("coverage.csv");
        CliRun run = CliRun.of("coverage", "--csv", csv.toString(), SMALL[0], SMALL[1], SMALL[2], SMALL[3]);
        assertThat(run.status()).as(run.transcript()).isEqualTo(CoverageCommand.EXIT_OK);
        List<String> lines = Files.readAllLines(csv);
        Coverage coverage = CatalogueOnScenes.measure(GradingScenes.builtIn(), 160, 120);
        assertThat(lines.get(0)).isEqualTo("Mistake,Scene,Pixels differing");
        assertThat(lines).hasSize(1 + 2 * (coverage.mistakes().size() + coverage.pairs().size()))
                .contains("far root,tick1.xml," + coverage.of(gfx.tick1.command.shared.behaviour.Variant.FAR_ROOT)
                        .pixels().get(0));
        assertThat(run.out()).contains("Caught by no scene:", "k_d swapped with k_s: no scene can show it");
    }

    @Test
    void thePageEscapesAScenesName() throws IOException {
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        Files.copy(Path.of("scenes/basic_scene.xml"), scenes.resolve("a<b>&'\".xml"));
        Path page = dir.resolve("coverage.html");
        CliRun run = CliRun.of("coverage", "--scenes", scenes.toString(), "--html", page.toString(), SMALL[0],
                SMALL[1], SMALL[2], SMALL[3]);
        assertThat(run.status()).as(run.transcript()).isEqualTo(CoverageCommand.EXIT_OK);
        assertThat(Files.readString(page)).contains("a&lt;b&gt;&amp;&#39;&quot;.xml").doesNotContain("a<b>");
    }

    @Test
    void aSceneThatCannotBeReadIsOneLineAndExitStatus2() throws IOException {
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        Files.writeString(scenes.resolve("bad.xml"), "<scene><sphere radius=\"-1\" colour=\"#FFFFFF\"/></scene>");
        CliRun run = CliRun.of("coverage", "--scenes", scenes.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(CoverageCommand.EXIT_USAGE);
        assertThat(run.err().lines()).as(run.err()).hasSize(1).allMatch(line -> line.contains("bad.xml:1:"));
    }

    /** docs/grading.md's catalogue says which default scenes catch each mistake; coverage at 640 x 480 decides. */
    @Test
    void theDocsCatalogueColumnIsWhatCoverageComputes() throws IOException {
        Coverage coverage = CatalogueOnScenes.measure(GradingScenes.builtIn(), 640, 480);
        List<String> expected = new ArrayList<>(), documented = new ArrayList<>();
        List<String> rows = Files.readAllLines(Path.of("docs/grading.md")).stream()
                .filter(line -> line.startsWith("| ") && line.endsWith(" |") && line.split(" \\| ").length == 3)
                .toList();
        coverage.mistakes().forEach(mistake -> {
            List<String> by = new ArrayList<>();
            for (int i = 0; i < coverage.scenes().size(); i++) {
                if (mistake.caughtBy(i)) {
                    by.add(coverage.scenes().get(i).equals("hidden.xml") ? "hidden" : coverage.scenes().get(i));
                }
            }
            expected.add(mistake.title() + ": " + (by.isEmpty() ? "neither" : String.join(", ", by)));
            rows.stream().filter(row -> row.startsWith("| " + mistake.title() + " | ")).forEach(row -> {
                String[] cells = row.substring(2, row.length() - 2).split(" \\| ");
                documented.add(cells[0] + ": " + cells[2]);
            });
        });
        assertThat(documented).as("docs/grading.md's catalogue, column \"caught by\"").isEqualTo(expected);
    }
}
