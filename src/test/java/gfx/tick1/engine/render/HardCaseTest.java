package gfx.tick1.engine.render;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The hard cases of {@code scenes/hard} (see docs/hard-cases.md) against the truth renderer.
 * Their golden images are checked by {@code GoldenImageTest} like every other scene's.
 */
@Order(5)   // one of the longest classes: it starts early (junit-platform.properties)
class HardCaseTest {

    private static final Path HARD = Path.of("scenes", "hard");
    private static final int WIDTH = GoldenImages.WIDTH, HEIGHT = GoldenImages.HEIGHT;
    private static final Map<Path, BufferedImage> TRUTH = new ConcurrentHashMap<>();

    static List<Path> hardCases() throws IOException {
        return GoldenImages.scenesUnder(HARD);
    }

    private static Scene load(Path scene) {
        return new SceneLoader(scene, false).getScene();
    }

    /** The truth image, made once per scene: it is the slow part. */
    private static BufferedImage truth(Path scene) {
        return TRUTH.computeIfAbsent(scene, s -> new TruthRenderer(WIDTH, HEIGHT).render(load(s)));
    }

    /** The default renderer's image, shared with the other classes that render the scene so. */
    private static BufferedImage byDefault(Path scene) {
        return ReferenceImages.of(scene);
    }

    private static ImageDifference againstTruth(Path scene, Intersection intersection) {
        BufferedImage image = intersection == Intersection.DEFAULT ? byDefault(scene)
                : new ReferenceRenderer(WIDTH, HEIGHT, intersection).render(load(scene));
        return ImageDifference.between(truth(scene), image);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("hardCases")
    void theDefaultRendererIsWithinOneLevelOfTheTruthOnEveryPixel(Path scene) {
        ImageDifference difference = againstTruth(scene, Intersection.DEFAULT);
        assertThat(difference.maxDifference()).as("%s against the truth: %s", scene, difference.summary())
                .isLessThanOrEqualTo(1);
    }

    /**
     * A NaN channel truncates to 0, so a NaN-derived pixel would be silently black in that channel:
     * the colours are traced again, as the image's were, at every pixel with a channel at 0 (on most hard
     * cases there is none), and none may be NaN.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("hardCases")
    void noColourTheDefaultRendererComputesIsNaN(Path scene) {
        Scene loaded = load(scene);
        BufferedImage image = byDefault(scene);
        Renderer renderer = new ReferenceRenderer(WIDTH, HEIGHT);
        Camera camera = new Camera(WIDTH, HEIGHT);
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                if (!hasAChannelAtZero(image.getRGB(x, y))) {
                    continue;
                }
                Vector3 colour = renderer.trace(loaded, camera.castRay(x, y));
                assertThat(Double.isNaN(colour.x) || Double.isNaN(colour.y) || Double.isNaN(colour.z))
                        .as("%s pixel (%d, %d) is %s", scene, x, y, colour).isFalse();
            }
        }
    }

    private static boolean hasAChannelAtZero(int rgb) {
        return (rgb & 0xFF0000) == 0 || (rgb & 0xFF00) == 0 || (rgb & 0xFF) == 0;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("hardCases")
    void noPixelIsBlackWhereTheTruthIsNot(Path scene) {
        BufferedImage image = byDefault(scene);
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                if ((image.getRGB(x, y) & 0xFFFFFF) == 0) {
                    assertThat(truth(scene).getRGB(x, y) & 0xFFFFFF).as("%s pixel (%d, %d) is black", scene, x, y)
                            .isLessThanOrEqualTo(0x010101);
                }
            }
        }
    }

    /**
     * What the handout's formula gets wrong, as measured (docs/hard-cases.md has the pictures).
     * Rows with 0 record that the handout's formula is within one level there too. A change in
     * any number means the HANDOUT variant no longer computes the handout's formula.
     */
    @ParameterizedTest(name = "{0}: {1} pixels off by more than 1 level, worst {2}")
    @CsvSource({
        "far-small-spheres,          8, 160",
        "giant-floor-3e15,         139,   2",
        "giant-floor-1e16,       47880,   9",
        "giant-floor-1e15,           0,   1",
        "giant-floor-1e12,           0,   1",
        "giant-floor-1e9,            0,   0",
        "giant-floor-1e6,            0,   0",
        "grazing,                    0,   0",
        "camera-inside-sphere,       0,   0",
        "behind-camera-touching,     0,   1",
        "touching-image-plane,       0,   0",
        "light-on-surface,           0,   0",
        "light-just-above-surface,   0,   0",
        "light-inside-sphere,        0,   0",
        "light-at-camera,            0,   0",
        "coincident-spheres,         0,   1",
        "concentric-spheres,         0,   1",
        "extreme-coordinates,        0,   0",
    })
    void theHandoutFormulaFailsExactlyWhereMeasured(String name, int pixelsOffByMoreThanOne, int worst) {
        ImageDifference difference = againstTruth(HARD.resolve(name + ".xml"), Intersection.HANDOUT);
        assertThat(difference.pixelsDifferingByMoreThan(1)).as("%s, handout formula: %s", name, difference.summary())
                .isEqualTo(pixelsOffByMoreThanOne);
        assertThat(difference.maxDifference()).as("%s, handout formula: %s", name, difference.summary())
                .isEqualTo(worst);
    }

    @Test
    void everyHardCaseHasAMeasuredHandoutRow() throws Exception {
        CsvSource rows = getClass().getDeclaredMethod("theHandoutFormulaFailsExactlyWhereMeasured",
                String.class, int.class, int.class).getAnnotation(CsvSource.class);
        List<String> measured = Arrays.stream(rows.value()).map(row -> row.split(",")[0].strip())
                .collect(Collectors.toList());
        List<String> cases = hardCases().stream().map(p -> p.getFileName().toString().replace(".xml", ""))
                .collect(Collectors.toList());
        assertThat(measured).as("rows of theHandoutFormulaFailsExactlyWhereMeasured")
                .containsExactlyInAnyOrderElementsOf(cases);
    }
}
