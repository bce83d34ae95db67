package gfx.tick1.engine.render;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import gfx.tick1.engine.scene.Sphere;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * On ordinary scenes the default renderer is the handout's formula, bit for bit: the course's
 * images must not move by a single level because the reference build became robust.
 */
class OrdinaryScenesTest {

    private static final Path SCENES = Path.of("scenes");
    private static final long SEED = 20240613;
    private static final int GENERATED = 300;

    static List<Path> ordinaryScenes() throws IOException {
        return GoldenImages.scenesUnder(SCENES).stream()
                .filter(p -> !p.startsWith(SCENES.resolve("hard"))).collect(Collectors.toList());
    }

    private static ImageDifference defaultAgainstHandout(Scene scene, int width, int height) {
        return ImageDifference.between(new ReferenceRenderer(width, height, Intersection.HANDOUT).render(scene),
                new ReferenceRenderer(width, height).render(scene));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("ordinaryScenes")
    void theDefaultRendererDrawsEachOrdinarySceneExactlyAsTheHandoutFormula(Path scene) {
        ImageDifference difference = ImageDifference.between(new ReferenceRenderer(GoldenImages.WIDTH,
                GoldenImages.HEIGHT, Intersection.HANDOUT).render(new SceneLoader(scene, false).getScene()),
                ReferenceImages.of(scene));
        assertThat(difference.differingPixels()).as("%s: %s", scene, difference.summary()).isZero();
    }

    /**
     * Many scenes, each at a small size: whether the two agree is a matter of each ray, and a pixel's ray is the same
     * computation at any size.
     */
    @Test
    void theDefaultRendererDrawsGeneratedOrdinaryScenesExactlyAsTheHandoutFormula() {
        Random random = new Random(SEED);
        for (int i = 0; i < GENERATED; i++) {
            Scene scene = OrdinaryScenes.generate(random);
            ImageDifference difference = defaultAgainstHandout(scene, 160, 120);
            assertThat(difference.differingPixels()).as("generated scene %d (seed %d): %s", i, SEED,
                    difference.summary()).isZero();
        }
    }

    /** Stronger than equal pixels: the same hit, to the last bit of s, for every ray and sphere. */
    @Test
    void onOrdinaryScenesEveryHitIsTheHandoutsToTheLastBit() {
        Random random = new Random(SEED + 1);
        Camera camera = new Camera(160, 120);
        long hits = IntStream.range(0, 50).mapToLong(i -> {
            Scene scene = OrdinaryScenes.generate(random);
            long count = 0;
            for (int y = 0; y < 120; y++) {
                for (int x = 0; x < 160; x++) {
                    Ray ray = camera.castRay(x, y);
                    for (Sphere sphere : scene.getObjects()) {
                        RaycastHit handout = Intersection.HANDOUT.find(sphere, ray);
                        RaycastHit robust = Intersection.ROBUST.find(sphere, ray);
                        assertThat(Double.doubleToLongBits(robust.getDistance()))
                                .as("s for %s and %s: handout %s, robust %s", sphere, ray, handout.getDistance(),
                                        robust.getDistance())
                                .isEqualTo(Double.doubleToLongBits(handout.getDistance()));
                        count += handout.isHit() ? 1 : 0;
                    }
                }
            }
            return count;
        }).sum();
        assertThat(hits).as("hits compared").isGreaterThan(50_000);
    }
}
