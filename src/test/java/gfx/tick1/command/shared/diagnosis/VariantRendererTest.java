package gfx.tick1.command.shared.diagnosis;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.render.GoldenImages;
import gfx.tick1.engine.render.ReferenceImages;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

@Order(8)   // one of the longest classes: it starts early (junit-platform.properties)
class VariantRendererTest {

    static Stream<Path> scenes() throws IOException {
        return GoldenImages.scenesUnder(Path.of("scenes")).stream();
    }

    /** The catalogue's "correct" entry may never drift from the reference renderer. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void correctVariantIsTheReferenceRendererPixelForPixel(Path file) {
        assertSameAsReference(ReferenceImages.of(file), new SceneLoader(file, false).getScene(), file.toString());
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {BundledScenes.TICK1, BundledScenes.HIDDEN})
    void correctVariantIsTheReferenceRendererOnTheBundledScenes(String name) {
        Scene scene = BundledScenes.load(name);
        assertSameAsReference(new ReferenceRenderer(GoldenImages.WIDTH, GoldenImages.HEIGHT).render(scene), scene,
                name);
    }

    private static void assertSameAsReference(BufferedImage reference, Scene scene, String name) {
        BufferedImage correct = new VariantRenderer(GoldenImages.WIDTH, GoldenImages.HEIGHT).render(scene,
                Variant.CORRECT);
        ImageDifference difference = ImageDifference.between(reference, correct);
        assertThat(difference.differingPixels()).as("%s: %s", name, difference.summary()).isZero();
    }

    static Stream<Variant> seenInImages() {
        return Variant.seenInImages().stream();
    }

    /** The mistakes the grading scenes cannot show, each with a scene that does. */
    private static final java.util.Map<Variant, String> SEEN_ONLY_ON = java.util.Map.of(
            Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT, "scenes/hard/camera-inside-sphere.xml",
            Variant.ROOTS_ACCEPTED_AT_ZERO, "src/test/resources/scenes/sphere-through-camera.xml");

    /**
     * Every entry of the catalogue that can show in an image shows on both grading scenes, even in
     * a small image: its render is diagnosed as itself, so no two entries are the same picture and
     * none is the correct one. A hit rejected on a negative root shows only where the camera is
     * inside a sphere, and a root accepted at s = 0 only where a sphere passes through the camera,
     * so they are checked on such scenes.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("seenInImages")
    void everyVariantIsTellableFromAllOthersOnTheGradingScenes(Variant variant) {
        List<String> names = SEEN_ONLY_ON.containsKey(variant) ? List.of(SEEN_ONLY_ON.get(variant))
                : BundledScenes.GRADING;
        for (String name : names) {
            Scene scene = name.endsWith(".xml") && name.contains("/") ? new SceneLoader(Path.of(name), false).getScene()
                    : BundledScenes.load(name);
            BufferedImage image = new VariantRenderer(160, 120).render(scene, variant);
            Diagnosis diagnosis = new Diagnoser().diagnose(image, scene);
            List<Diagnosis.Candidate> top = diagnosis.top(2);
            assertThat(top.get(0).variant()).as("%s: %s", name, diagnosis.report()).isEqualTo(variant);
            assertThat(top.get(1).exactShare()).as("%s: runner-up %s", name, top.get(1).variant()).isLessThan(1);
            assertThat(diagnosis.verdict()).isEqualTo(variant.isCorrect() ? Diagnosis.Verdict.CORRECT
                    : Diagnosis.Verdict.EXPLAINED);
        }
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {BundledScenes.TICK1, BundledScenes.HIDDEN})
    void theMistakesOfRaysFromInsideOrOnASphereDrawTheCorrectImageOnTheGradingScenes(String name) {
        Scene scene = BundledScenes.load(name);
        for (Variant variant : SEEN_ONLY_ON.keySet()) {
            Diagnosis diagnosis = new Diagnoser().diagnose(new VariantRenderer(160, 120).render(scene, variant), scene);
            assertThat(diagnosis.verdict()).as(String.join("\n", diagnosis.report()))
                    .isEqualTo(Diagnosis.Verdict.CORRECT);
            assertThat(diagnosis.alikeCorrect()).containsExactlyInAnyOrderElementsOf(SEEN_ONLY_ON.keySet());
        }
    }
}
