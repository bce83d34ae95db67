package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.render.GoldenImages;
import gfx.tick1.engine.render.ReferenceImages;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every scene in {@code scenes/} renders to its reference image pixel for pixel. On a mismatch
 * the actual image and a heat map of the differences are left in {@code build/golden/}.
 */
class GoldenImageTest {

    private static final Path SCENES = Path.of("scenes");
    private static final Path REFERENCES = Path.of("reference-images");
    private static final Path FAILURES = Path.of("build", "golden");

    static List<Path> scenes() throws IOException {
        return GoldenImages.scenesUnder(SCENES);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void rendersExactlyAsItsReferenceImage(Path scene) throws IOException {
        Path reference = GoldenImages.referenceFor(SCENES, REFERENCES, scene);
        assertThat(reference).as("reference image for %s (make it with: gradle updateReferenceImages)", scene)
                .exists();
        BufferedImage expected = ImageIO.read(reference.toFile());
        BufferedImage actual = ReferenceImages.of(scene);

        ImageDifference difference = ImageDifference.between(expected, actual);
        if (difference.differingPixels() > 0) {
            String name = SCENES.relativize(scene).toString().replace('/', '_').replace(".xml", "");
            Files.createDirectories(FAILURES);
            PngOutput.write(actual, FAILURES.resolve(name + "-actual.png"));
            PngOutput.write(difference.heatMap(), FAILURES.resolve(name + "-diff.png"));
        }
        assertThat(difference.differingPixels())
                .as("%s: %s; actual image and heat map in %s", scene, difference.summary(), FAILURES)
                .isZero();
    }

    @Test
    void everyReferenceImageBelongsToAScene() throws IOException {
        List<Path> expected = scenes().stream()
                .map(s -> GoldenImages.referenceFor(SCENES, REFERENCES, s)).collect(Collectors.toList());
        try (Stream<Path> files = Files.walk(REFERENCES)) {
            assertThat(files.filter(p -> p.toString().endsWith(".png")))
                    .as("reference images without a scene (stale goldens)").allMatch(expected::contains);
        }
    }

    @Test
    void theSuiteHasTheHandoutScenesAndAtLeastEightMore() throws IOException {
        assertThat(scenes()).contains(SCENES.resolve("basic_scene.xml"), SCENES.resolve("tick1.xml"));
        assertThat(scenes().size()).isGreaterThanOrEqualTo(10);
    }
}
