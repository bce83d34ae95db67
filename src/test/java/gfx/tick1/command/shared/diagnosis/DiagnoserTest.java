package gfx.tick1.command.shared.diagnosis;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.engine.image.PngInput;
import gfx.tick1.engine.render.GoldenImages;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The diagnosis names the handout's own figures, read from {@code ../shared/handout-figures}
 * when it exists (never copied in), and never calls a correct image a mistake.
 */
@Order(14)   // one of the longest classes: it starts early (junit-platform.properties)
class DiagnoserTest {

    private static final Path FIGURES = Path.of("..", "shared", "handout-figures");
    /** The handout's Figure 6 images carry a red frame this wide, drawn for the handout. */
    private static final int FIGURE_6_FRAME = 12;

    private static Path requireFigure(String file) {
        Path figure = FIGURES.resolve(file);
        assumeTrue(Files.exists(figure), "skipped: the handout's figure " + figure.getFileName()
                + " is not on this machine");
        return figure;
    }

    private static Diagnosis diagnoseFigure(String file, int border) throws IOException {
        return new Diagnoser(border, 1).diagnose(PngInput.read(requireFigure(file)),
                BundledScenes.load(BundledScenes.TICK1));
    }

    /**
     * An image that is exactly a mistake's render, drawn by code whose answers are not that
     * mistake's (max(0, (R.V)^n) draws the image of (R.V)^n where every n is even): the image says
     * which render it is, never that the mistake is its cause, nor what to reread for it.
     */
    @Test
    void anExactMatchWhoseModelTheAnswersRuleOutIsNeverGivenAsTheCause() {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        Diagnosis diagnosis = new Diagnoser().diagnose(new VariantRenderer(160, 120).render(scene,
                Variant.UNCLAMPED_R_DOT_V), scene);
        String report = String.join("\n", diagnosis.report(true, Set.of(Variant.UNCLAMPED_R_DOT_V)));
        assertThat(diagnosis.verdict()).as(report).isEqualTo(Diagnosis.Verdict.EXPLAINED);
        assertThat(report).as("the report").contains("every pixel matches its render")
                .doesNotContain("likely cause", "reread");
    }

    /**
     * A grade ranks only the entries the code's answers leave possible: one they rule out is not
     * among the candidates at all, however close its render, and the correct entry always is.
     */
    @Test
    void anEntryLeftOutOfThoseConsideredIsNoCandidate() {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        BufferedImage image = new VariantRenderer(160, 120).render(scene, Variant.UNCLAMPED_N_DOT_L);
        Set<Variant> considered = java.util.EnumSet.allOf(Variant.class);
        considered.remove(Variant.UNCLAMPED_R_DOT_V);
        considered.remove(Variant.CORRECT);

        Diagnosis diagnosis = new Diagnoser().diagnose(image, scene, null, considered);

        assertThat(diagnosis.candidates()).as("the candidates").extracting(Diagnosis.Candidate::variant)
                .doesNotContain(Variant.UNCLAMPED_R_DOT_V).contains(Variant.CORRECT, Variant.UNCLAMPED_N_DOT_L);
        assertThat(diagnosis.closest().variant()).as("the closest").isEqualTo(Variant.UNCLAMPED_N_DOT_L);
    }

    /** One pixel off the correct render: the correct image is no candidate, and a ruled-out entry is none either. */
    @Test
    void anUnsureImageNamesNeitherTheCorrectImageNorARuledOutEntryAsACandidate() {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        BufferedImage image = new VariantRenderer(160, 120).render(scene, Variant.CORRECT);
        image.setRGB(80, 60, 0xFFFFFF);
        Diagnosis diagnosis = new Diagnoser().diagnose(image, scene);
        Variant nearestMistake = diagnosis.candidates().stream().map(Diagnosis.Candidate::variant)
                .filter(v -> !v.isCorrect()).findFirst().orElseThrow();
        String report = String.join("\n", diagnosis.report(true, Set.of(nearestMistake)));
        assertThat(diagnosis.verdict()).as(report).isEqualTo(Diagnosis.Verdict.UNSURE);
        assertThat(report).as("the report").contains("1 pixel differs from it")
                .doesNotContain(". the correct image", "= the correct image", ". " + nearestMistake.title(),
                        "= " + nearestMistake.title(),
                        "if it is " + nearestMistake.title());
    }

    @ParameterizedTest(name = "{0} is {1}")
    @CsvSource({
        "fig4-flat-colour.png, FLAT_COLOUR, 0",
        "fig5a-ambient.png, AMBIENT_ONLY, 0",
        "fig6a-unnormalised-L-V.png, UNNORMALISED_L_V, " + FIGURE_6_FRAME,
        "fig6b-no-max-NdotL.png, UNCLAMPED_N_DOT_L, " + FIGURE_6_FRAME,
        "fig6c-no-max-RdotV.png, UNCLAMPED_R_DOT_V, " + FIGURE_6_FRAME})
    void namesTheHandoutsFiguresPixelForPixel(String file, Variant expected, int border) throws IOException {
        Diagnosis diagnosis = diagnoseFigure(file, border);
        assertThat(diagnosis.closest().variant()).as(String.join("\n", diagnosis.report())).isEqualTo(expected);
        assertThat(diagnosis.closest().exactShare()).as("the spec's rule reproduces the figure exactly").isEqualTo(1);
        assertThat(diagnosis.verdict()).isEqualTo(Diagnosis.Verdict.EXPLAINED);
    }

    /**
     * Figure 1 was made by an older build: up to 3 levels off the correct render on 15,350 pixels.
     * The correct image stays its closest entry, but beyond the 1-level tolerance it is not called
     * correct.
     */
    @Test
    void findsFigure1ClosestToCorrectWithoutCallingItCorrect() throws IOException {
        Diagnosis diagnosis = diagnoseFigure("fig1-final.png", 0);
        assertThat(diagnosis.closest().variant()).as(String.join("\n", diagnosis.report())).isEqualTo(Variant.CORRECT);
        assertThat(diagnosis.verdict()).isEqualTo(Diagnosis.Verdict.UNSURE);
    }

    /** Figure 5b was made with another set-up: its two closest entries are level, and shown as a tie. */
    @Test
    void showsTheNearTieOnFigure5bAsATie() throws IOException {
        Diagnosis diagnosis = new Diagnoser(0, 1).diagnose(PngInput.read(requireFigure("fig5b-ambient-diffuse.png")),
                BundledScenes.load(BundledScenes.TICK1));
        String report = String.join("\n", diagnosis.report());
        assertThat(diagnosis.verdict()).as(report).isEqualTo(Diagnosis.Verdict.UNSURE);
        assertThat(report).contains("  1= ambient + diffuse", "  1= R reflected the wrong way", "in a near tie")
                .doesNotContain("likely cause");
    }

    static Stream<Path> scenes() throws IOException {
        return GoldenImages.scenesUnder(Path.of("scenes")).stream();
    }

    /**
     * What the reference renderer draws of any scene is diagnosed correct. At 160 x 120, not the golden images'
     * 640 x 480: the verdict says which entry's render the image is, at any size, and VariantRendererTest holds the
     * correct entry to the reference renderer at 640 x 480.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void everySceneAsTheReferenceRendererDrawsItIsDiagnosedCorrect(Path scene) {
        Scene loaded = new SceneLoader(scene, false).getScene();
        assertDiagnosedCorrect(new ReferenceRenderer(160, 120).render(loaded), loaded);
    }

    /** The course's scenes' reference images, as a student who renders them right diagnoses them. */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"scenes/tick1.xml", "scenes/basic_scene.xml"})
    void theCoursesReferenceImagesAreDiagnosedCorrect(Path scene) throws IOException {
        Path reference = GoldenImages.referenceFor(Path.of("scenes"), Path.of("reference-images"), scene);
        assertDiagnosedCorrect(PngInput.read(reference), new SceneLoader(scene, false).getScene());
    }

    private static void assertDiagnosedCorrect(BufferedImage image, Scene scene) {
        Diagnosis diagnosis = new Diagnoser().diagnose(image, scene);
        assertThat(diagnosis.closest().variant()).as(String.join("\n", diagnosis.report())).isEqualTo(Variant.CORRECT);
        assertThat(diagnosis.closest().exactShare()).isEqualTo(1);
        assertThat(diagnosis.verdict()).isEqualTo(Diagnosis.Verdict.CORRECT);
    }

    /**
     * The ranking counts only the pixels where some entry draws a sphere: the background, which
     * every entry draws alike, would otherwise give even "background only" most of a correct image.
     */
    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.ValueSource(strings = {BundledScenes.TICK1, BundledScenes.BASIC})
    void theRankingCountsOnlyThePixelsWhereSomeEntryDrawsASphere(String name) {
        Scene scene = BundledScenes.load(name);
        Diagnosis diagnosis = new Diagnoser().diagnose(new VariantRenderer(160, 120).render(scene, Variant.CORRECT),
                scene);
        Diagnosis.Candidate background = diagnosis.candidates().stream()
                .filter(c -> c.variant() == Variant.BACKGROUND_ONLY).findFirst().orElseThrow();
        assertThat(diagnosis.spherePixels()).isPositive().isLessThan(160 * 120);
        double onTheFrame = background.difference().shareWithin(0);
        assertThat(onTheFrame).as("on the whole frame").isGreaterThan(0.3);
        assertThat(background.exactShare()).as("on the sphere pixels").isLessThan(onTheFrame / 2);
    }

    /**
     * One pixel one level off: never called correct, with the tolerance or without (grade fails
     * it), but said to be within a level of the correct render, with the count and a possible cause.
     */
    @ParameterizedTest(name = "tolerance {0}")
    @org.junit.jupiter.params.provider.ValueSource(ints = {0, 1})
    void anImageOneLevelOffIsNeverCalledCorrect(int tolerance) {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        BufferedImage image = new VariantRenderer(160, 120).render(scene, Variant.CORRECT);
        image.setRGB(80, 60, image.getRGB(80, 60) + 1); // blue one level up, the sphere's centre
        Diagnosis diagnosis = new Diagnoser(0, tolerance).diagnose(image, scene, BundledScenes.TICK1);
        String report = String.join("\n", diagnosis.report());
        assertThat(diagnosis.verdict()).as(report).isEqualTo(Diagnosis.Verdict.LEVEL_OFF_CORRECT);
        assertThat(report).as("the report").doesNotContain("verdict: correct", "full Phong model", "likely cause")
                .contains("verdict: not correct: 1 pixel of 19200 differs from the correct render of tick1.xml, by 1 "
                        + "level in a channel", "possible cause: the same formulas computed in float");
    }

    /**
     * An image whose pixels differ from the correct render is never ranked next to it: the correct image is
     * neither its closest entry nor in its top three, whether the image is a level off it or a mistake's.
     */
    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.EnumSource(value = Variant.class, names = {"CORRECT", "UNCLAMPED_N_DOT_L"})
    void anImageThatIsNotTheCorrectRenderNeverListsTheCorrectImage(Variant drawn) {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        BufferedImage image = new VariantRenderer(160, 120).render(scene, drawn);
        if (drawn.isCorrect()) {
            image.setRGB(80, 60, image.getRGB(80, 60) + 1); // blue one level up, the sphere's centre
        }
        String report = String.join("\n", new Diagnoser(0, 1).diagnose(image, scene, BundledScenes.TICK1).report());
        assertThat(report).as("the report").doesNotContain("closest: the correct image", ". the correct image",
                "= the correct image");
    }

    /** What to reread for a mistake of the starter code's part is named as such, never as a section of the handout. */
    @Test
    void aRereadLineForTheStarterCodeDoesNotCallItTheHandout() {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        Diagnosis diagnosis = new Diagnoser().diagnose(new VariantRenderer(160, 120).render(scene,
                Variant.ROUNDED_BYTES), scene, BundledScenes.TICK1);
        String report = String.join("\n", diagnosis.report(true));

        assertThat(report).as("the report").contains("reread: the starter code's Renderer.render")
                .doesNotContain("handout the ");
    }

    /** The correct render with every channel of every pixel moved half the range: far from every entry's. */
    private static BufferedImage farFromEveryEntry(Scene scene) {
        BufferedImage image = new VariantRenderer(160, 120).render(scene, Variant.CORRECT);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                image.setRGB(x, y, image.getRGB(x, y) ^ 0x808080);
            }
        }
        return image;
    }

    /** An unsure image's candidates each get some sphere pixel exactly right: one with none is no lead. */
    @Test
    void noCandidateOfAnUnsureImageHasNoPixelExact() {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        BufferedImage image = farFromEveryEntry(scene);
        String report = String.join("\n", new Diagnoser().diagnose(image, scene, BundledScenes.TICK1).report());

        assertThat(report).as("the report").contains("verdict: unsure").doesNotContain(" 0.000% of pixels exact");
    }

    /** Where tick1 had the code render the scene itself (a grade), a weak match never suggests another scene. */
    @Test
    void aWeakMatchOfASceneTick1RenderedItselfDoesNotSuggestAnotherScene() {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        BufferedImage image = farFromEveryEntry(scene);
        Diagnosis diagnosis = new Diagnoser().diagnose(image, scene, BundledScenes.TICK1);

        assertThat(String.join("\n", diagnosis.report(true, Set.of()))).as("the report of an image given")
                .contains("another scene");
        assertThat(String.join("\n", diagnosis.report(true, Set.of(), true))).as("the report of a scene rendered")
                .doesNotContain("another scene");
    }

    /** The handout's figures all show tick1.xml: on another scene no entry is named with one. */
    @ParameterizedTest(name = "{0}")
    @CsvSource({"tick1.xml, true", "basic_scene.xml, false"})
    void entriesAreNamedWithTheirFiguresOnlyOnTheSceneTheFiguresShow(String name, boolean figures) {
        Scene scene = BundledScenes.load(name);
        Diagnosis diagnosis = new Diagnoser().diagnose(new VariantRenderer(160, 120).render(scene,
                Variant.UNCLAMPED_N_DOT_L), scene, name);
        String report = String.join("\n", diagnosis.report());
        assertThat(diagnosis.figures()).as(report).isEqualTo(figures);
        if (figures) {
            assertThat(report).as(report).contains("N.L not clamped (Figure 6b)");
        } else {
            assertThat(report).as(report).contains("N.L not clamped").doesNotContain("(Figure", "(like Figure");
        }
    }
}
