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
        assertThat(run.out()).contains("closest: correct (Figure 1)", "verdict: correct").doesNotContain("reread");
    }

    @Test
    void aCorrectRenderOfTheKitsBasicSceneIsRecognisedAndCorrect() throws IOException {
        Path image = render("scenes/basic_scene.xml", Variant.CORRECT, 160, 120);
        CliRun run = CliRun.of("diagnose", image.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_CORRECT);
        assertThat(run.out()).contains("as a render of basic_scene.xml:", "verdict: correct")
                .doesNotContain("background only");
    }

    @Test
    void anImageOfAnotherSceneAsksForTheScene() throws IOException {
        Path image = render("scenes/hundred-spheres.xml", Variant.CORRECT, 160, 120);
        CliRun run = CliRun.of("diagnose", image.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_CANNOT_DIAGNOSE);
        assertThat(run.err()).isEqualTo("tick1 diagnose: " + image
                + ": not a render of tick1.xml or basic_scene.xml; give the scene with --scene"
                + System.lineSeparator());
        assertThat(run.out()).isEmpty();
    }

    @Test
    void aMistakeSeenOnlyWithTheCameraInsideASphereIsNamedOnSuchAScene() throws IOException {
        String scene = "scenes/hard/camera-inside-sphere.xml";
        Path image = render(scene, Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT, 160, 120);
        CliRun run = CliRun.of("diagnose", image.toString(), "--scene", scene);
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_NOT_CORRECT);
        assertThat(run.out()).contains("verdict: hit rejected when either root is negative: every pixel matches",
                "reread: handout section 4, steps 4 to 6");
    }

    @Test
    void anImageNoEntryExplainsExitsThreeWithCandidatesAndNoCause() throws IOException {
        Path image = render("scenes/tick1.xml", Variant.CORRECT, 160, 120);
        java.awt.image.BufferedImage picture = javax.imageio.ImageIO.read(image.toFile());
        picture.setRGB(80, 60, 0xFFFFFF); // one pixel no entry draws
        PngOutput.write(picture, image);
        CliRun run = CliRun.of("diagnose", image.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_UNSURE);
        assertThat(run.out()).contains("verdict: unsure: no entry of the catalogue explains this image exactly",
                "candidates, closest first:", "  1. correct (Figure 1)")
                .doesNotContain("likely cause", "full Phong model", "closest: ");
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
