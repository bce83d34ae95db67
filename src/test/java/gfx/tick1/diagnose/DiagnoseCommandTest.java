package gfx.tick1.diagnose;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.image.PngOutput;
import gfx.tick1.scene.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code tick1 diagnose} through the real entry point. */
class DiagnoseCommandTest {

    @TempDir
    Path dir;

    private Path render(String scene, Variant variant, int width, int height) throws IOException {
        Path image = dir.resolve(variant + ".png");
        PngOutput.write(new VariantRenderer(width, height).render(
                new SceneLoader(Path.of(scene), false).getScene(), variant), image);
        return image;
    }

    @Test
    void aMistakeIsNamedExplainedAndExitsOne() throws IOException {
        Path image = render("scenes/tick1.xml", Variant.UNCLAMPED_N_DOT_L, 160, 120);
        CliRun run = CliRun.of("diagnose", image.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_NOT_CORRECT);
        assertThat(run.out()).contains("closest: N.L not clamped (Figure 6b) (100.000% of pixels exact",
                "top three:", "  1. N.L not clamped", "likely cause: the diffuse term uses N.L",
                "reread: handout section 5, Figure 6(b)");
        assertThat(run.err()).isEmpty();
    }

    @Test
    void theCorrectImageExitsZero() throws IOException {
        Path image = render("scenes/basic_scene.xml", Variant.CORRECT, 64, 48);
        CliRun run = CliRun.of("diagnose", image.toString(), "--scene", "scenes/basic_scene.xml");
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_CORRECT);
        assertThat(run.out()).contains("closest: correct (Figure 1)").doesNotContain("reread");
    }

    @Test
    void anUnreadableImageOrSceneGivesOneLineAndExitTwo() throws IOException {
        Path text = dir.resolve("x.png");
        Files.writeString(text, "no");
        Path image = render("scenes/tick1.xml", Variant.CORRECT, 32, 24);
        for (String[] args : new String[][] {{"diagnose", text.toString()},
                {"diagnose", image.toString(), "--scene", dir.resolve("missing.xml").toString()},
                {"diagnose", image.toString(), "--border", "12"}}) {
            CliRun run = CliRun.of(args);
            assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_CANNOT_DIAGNOSE);
            assertThat(run.err()).startsWith("tick1 diagnose: ");
            assertThat(run.err().lines()).hasSize(1);
        }
    }
}
