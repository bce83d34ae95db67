package gfx.tick1.command.diagnose;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.diagnosis.FloatShading;
import gfx.tick1.command.shared.diagnosis.VariantRenderer;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.scene.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

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
    void theCorrectImageExitsZeroAndNamesNoFigureOfAnotherScene() throws IOException {
        Path image = render("scenes/basic_scene.xml", Variant.CORRECT, 64, 48);
        CliRun run = CliRun.of("diagnose", image.toString(), "--scene", "scenes/basic_scene.xml");
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_CORRECT);
        assertThat(run.out()).as(run.transcript()).contains("compared with scenes/basic_scene.xml:",
                "closest: the correct image (100.000%", "verdict: correct: every pixel is the correct render's of "
                        + "scenes/basic_scene.xml.").doesNotContain("reread", "Figure", "scene differs");
    }

    @Test
    void aCorrectRenderOfTick1IsCorrectAndNamedWithFigure1() throws IOException {
        Path image = render("scenes/tick1.xml", Variant.CORRECT, 160, 120);
        CliRun run = CliRun.of("diagnose", image.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_CORRECT);
        assertThat(run.out()).as(run.transcript()).contains("compared with tick1.xml:",
                "verdict: correct: every pixel is the correct render's of tick1.xml.", "(Figure 1).")
                .doesNotContain("scene differs", "outlines");
    }

    /** The correct code's render of tick1.xml with one value of the scene file changed. */
    private Path renderOfTick1With(String value, String changed) throws IOException {
        String scene = Files.readString(Path.of("scenes/tick1.xml"));
        assertThat(scene).as("the value to change").containsOnlyOnce(value);
        Path file = dir.resolve("changed.xml");
        Files.writeString(file, scene.replace(value, changed));
        return render(file.toString(), Variant.CORRECT, 160, 120);
    }

    @ParameterizedTest(name = "{2}")
    @CsvSource(delimiter = '|', value = {
        "colour=\"#555555\" | colour=\"#333333\" | ambient #333333 where the handout's section 3 asks for #555555",
        "y=\"-0.16\" | y=\"0.16\" | sphere 1's centre (0.55, 0.16, 3.5) where the handout's section 3 asks for "
            + "(0.55, -0.16, 3.5)",
        "intensity=\"120\" | intensity=\"100\" | the point light's intensity 100 where the handout's section 3 asks "
            + "for 120",
        "colour=\"#FF1D25\" | colour=\"#FF0000\" | sphere 2's colour #FF0000 where the handout's section 3 asks for "
            + "#FF1D25"})
    void aSceneFileOneValueAwayFromSection3IsNamedNotBlamedOnTheCode(String value, String changed, String named)
            throws IOException {
        CliRun run = CliRun.of("diagnose", renderOfTick1With(value, changed).toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_NOT_CORRECT);
        assertThat(run.out()).as(run.transcript()).contains("compared with tick1.xml:",
                "verdict: the scene differs: every pixel is the correct render of tick1.xml with one value changed: "
                        + named + ".", "reread: handout section 3, \"Define a new scene\".")
                .doesNotContain("background only", "clamped", "candidates");
    }

    /**
     * A sphere's colour four levels off in blue: tick1.xml's outlines, colours no entry and no one
     * slip explain. The spheres are where the handout's are, so nothing blames the scene file: the
     * facts are given (a code mistake no entry knows gives the same image).
     */
    @Test
    void tick1sOutlinesWithColoursNothingExplainsGiveTheFactsWithoutSceneFileAdvice() throws IOException {
        CliRun run = CliRun.of("diagnose", renderOfTick1With("#FF1D25", "#FF1D29").toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_UNSURE);
        assertThat(run.out()).as(run.transcript()).contains("verdict: unsure: ",
                "the spheres' outlines are exactly those of tick1.xml, but no entry of the catalogue explains their "
                        + "colours.").doesNotContain("verdict: correct", "scene file");
    }

    /**
     * The correct code's render of tick1.xml with its shading in float is a level off the correct
     * render in places: its spheres are where the handout's are, so no line suggests that the
     * scene file differs.
     */
    @Test
    void aRenderALevelOffTheCorrectOneGivesNoSceneFileAdvice() throws IOException {
        Path image = dir.resolve("float.png");
        PngOutput.write(FloatShading.render(new SceneLoader(Path.of("scenes/tick1.xml"), false).getScene(), 160, 120),
                image);
        CliRun run = CliRun.of("diagnose", image.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_NOT_CORRECT);
        assertThat(run.out()).as(run.transcript()).doesNotContain("scene file");
    }

    /**
     * The correct code with its shading in float: a few pixels a level off the correct render.
     * Never correct (grade fails it); the count and the possible cause are said.
     */
    @Test
    void shadingInFloatIsNotCorrectAndSaysHowManyPixelsDifferAndWhy() throws IOException {
        gfx.tick1.engine.scene.Scene scene = new SceneLoader(Path.of("scenes/tick1.xml"), false).getScene();
        java.awt.image.BufferedImage inFloat = FloatShading.render(scene, 160, 120);
        gfx.tick1.engine.image.ImageDifference difference = gfx.tick1.engine.image.ImageDifference.between(
                new VariantRenderer(160, 120).render(scene, Variant.CORRECT), inFloat);
        assertThat(difference.differingPixels()).as("float moves some pixels").isPositive();
        assertThat(difference.maxDifference()).as("by a level at most").isEqualTo(1);
        Path image = dir.resolve("float.png");
        PngOutput.write(inFloat, image);
        CliRun run = CliRun.of("diagnose", image.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_NOT_CORRECT);
        assertThat(run.out()).as(run.transcript()).contains("verdict: not correct: " + difference.differingPixels()
                + " pixel", " of 19200 differ", "from the correct render of tick1.xml, by 1 level in a channel",
                "possible cause: the same formulas computed in float")
                .doesNotContain("verdict: correct", "full Phong model");
    }

    @Test
    void aCorrectRenderOfTheKitsBasicSceneIsRecognisedAndCorrect() throws IOException {
        Path image = render("scenes/basic_scene.xml", Variant.CORRECT, 160, 120);
        CliRun run = CliRun.of("diagnose", image.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_CORRECT);
        assertThat(run.out()).contains("compared with basic_scene.xml:", "verdict: correct")
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
                "the nearest render is the correct one, but 1 pixel differs from it", "candidates, closest first:")
                .doesNotContain("likely cause", "full Phong model", "closest: ", ". the correct image",
                        "= the correct image");
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

    @Test
    void aJpegOfACorrectRenderIsRefusedInOneLineNotDiagnosed() throws IOException {
        Path png = render("scenes/tick1.xml", Variant.CORRECT, 160, 120);
        Path jpeg = dir.resolve("real.jpg");
        javax.imageio.ImageIO.write(javax.imageio.ImageIO.read(png.toFile()), "jpeg", jpeg.toFile());
        CliRun run = CliRun.of("diagnose", jpeg.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiagnoseCommand.EXIT_CANNOT_DIAGNOSE);
        assertThat(run.err()).startsWith("tick1 diagnose: " + jpeg + ": a JPEG image, not a PNG: ");
        assertThat(run.err().lines()).hasSize(1);
        assertThat(run.out()).as("no verdict on a lossy copy").isEmpty();
    }
}
