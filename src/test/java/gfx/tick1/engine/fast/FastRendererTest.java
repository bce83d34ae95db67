package gfx.tick1.engine.fast;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.fast.FastRenderer.SphereSearch;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.GoldenImages;
import gfx.tick1.engine.render.ReferenceImages;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.render.SamplePattern;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import gfx.tick1.engine.scene.Sphere;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** The fast kernel against its oracle, the readable Renderer: the same pixels, always. */
@Order(9)   // one of the longest classes: it starts early (junit-platform.properties)
class FastRendererTest {

    static List<Path> scenes() throws IOException {
        return GoldenImages.scenesUnder(Path.of("scenes"));
    }

    private static Scene load(Path scene) {
        return new SceneLoader(scene, false).getScene();
    }

    private static void assertSamePixels(BufferedImage expected, BufferedImage actual, String what) {
        ImageDifference difference = ImageDifference.between(expected, actual);
        assertThat(difference.differingPixels()).as("%s: %s", what, difference.summary())
                .isZero();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void matchesTheReadableRendererOnEveryRepositoryScene(Path scene) {
        BufferedImage expected = ReferenceImages.of(scene);
        assertSamePixels(expected, new FastRenderer(GoldenImages.WIDTH, GoldenImages.HEIGHT, new SamplePattern(1))
                .render(load(scene)), scene.toString());
    }

    static List<Path> hardScenes() throws IOException {
        return GoldenImages.scenesUnder(Path.of("scenes/hard"));
    }

    /**
     * The default method, {@link Intersection#DEFAULT}, is held to the readable code on every hard case at
     * 640x480 already: the hard cases are among the repository's scenes.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("hardScenes")
    void matchesTheReadableRendererWithTheOtherIntersectionMethodsOnTheHardCases(Path scene) {
        for (Intersection intersection : EnumSet.complementOf(EnumSet.of(Intersection.DEFAULT))) {
            BufferedImage expected = new ReferenceRenderer(320, 240, intersection).render(load(scene));
            assertSamePixels(expected,
                    new FastRenderer(320, 240, new SamplePattern(1), intersection).render(load(scene)),
                    scene + " with " + intersection);
        }
    }

    @ParameterizedTest(name = "{0} samples")
    @ValueSource(ints = {2, 4, 5, 16})
    void matchesTheReadableRendererWhenAntiAliasing(int samples) {
        Scene scene = load(Path.of("scenes/tick1.xml"));
        SamplePattern pattern = new SamplePattern(samples);
        BufferedImage expected = new ReferenceRenderer(160, 120).render(scene, pattern);
        assertSamePixels(expected, new FastRenderer(160, 120, pattern).render(scene), samples + " samples");
    }

    /**
     * A crowd of spheres, a fifth of them duplicated exactly, drawn by the readable code, brute force and
     * the BVH. Whether the BVH finds a ray's nearest sphere, and the earlier of two coincident ones, is a
     * matter of each ray: a small image of the crowd still holds hundreds of pixels an exact tie decides
     * (the test counts them), and the readable code, which tests every sphere on every ray, costs less.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void bvhAndBruteForceAgreeOnLargeScenesIncludingExactTies(long seed) {
        Scene scene = crowd(seed, 1500, false);
        BufferedImage readable = new ReferenceRenderer(CROWD_WIDTH, CROWD_HEIGHT).render(scene);
        BufferedImage brute = crowdBy(SphereSearch.BRUTE_FORCE, scene);
        BufferedImage bvh = crowdBy(SphereSearch.BVH, scene);
        ImageDifference ties = ImageDifference.between(bvh, crowdBy(SphereSearch.BVH, crowd(seed, 1500, true)));
        assertThat(ties.differingPixels()).as("pixels an exact tie decides").isGreaterThan(300);
        assertSamePixels(brute, bvh, "BVH vs brute force");
        assertSamePixels(readable, bvh, "BVH vs readable");
    }

    /** The size of the crowd's image: its spheres still cover thousands of pixels. */
    private static final int CROWD_WIDTH = 100, CROWD_HEIGHT = 75;

    private static BufferedImage crowdBy(SphereSearch search, Scene scene) {
        return new FastRenderer(CROWD_WIDTH, CROWD_HEIGHT, new SamplePattern(1), search, Intersection.DEFAULT)
                .render(scene);
    }

    @Test
    void theBvhFindsTheEarlierOfTwoCoincidentSpheres() {
        Scene scene = new Scene();
        for (int i = 0; i < 20; i++) {
            scene.addObject(new Sphere(new Vector3(i - 10, 0, 30), 0.4, new Vector3(0, 0, 1)));
        }
        scene.addObject(new Sphere(new Vector3(0, 0, 5), 1, new Vector3(1, 0, 0)));
        scene.addObject(new Sphere(new Vector3(0, 0, 5), 1, new Vector3(0, 1, 0)));
        int centre = new FastRenderer(64, 48, new SamplePattern(1), SphereSearch.BVH, Intersection.DEFAULT)
                .render(scene).getRGB(32, 24) & 0xFFFFFF;
        assertThat(centre).as("the red sphere comes first in the file").isEqualTo(0xFF0000);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(doubles = {Double.NaN, Double.NEGATIVE_INFINITY, -1, -0.0, 0.0, Double.MIN_VALUE, 0.1, 0.5,
        0.9999999999999999, 1, 1.0000000000000002, 2, Double.POSITIVE_INFINITY})
    void everyChannelValueBecomesTheReadableCodesByte(double channel) {
        // An unlit white sphere's colour is the ambient light itself: every channel value reaches
        // the byte conversion as it is, NaN and infinities included.
        Scene scene = new Scene();
        scene.setAmbientLight(new Vector3(channel));
        scene.addObject(new Sphere(new Vector3(0, 0, 5), 1, new Vector3(1)));
        assertSamePixels(new ReferenceRenderer(16, 12).render(scene),
                new FastRenderer(16, 12, new SamplePattern(1)).render(scene),
                "ambient " + channel);
    }

    @Test
    void producesAStandardRgbImage() {
        BufferedImage image = new FastRenderer(8, 6, new SamplePattern(1)).render(new Scene());
        assertThat(image.getType()).isEqualTo(BufferedImage.TYPE_INT_RGB);
        assertThat(image.getRGB(3, 3) & 0xFFFFFF).isEqualTo(0x191919);
    }

    @Test
    void antiAliasingGivesTheSameImageOnEveryRun() {
        Scene scene = load(Path.of("scenes/hundred-spheres.xml"));
        SamplePattern pattern = new SamplePattern(4);
        assertSamePixels(new FastRenderer(160, 120, pattern).render(scene),
                new FastRenderer(160, 120, pattern).render(scene), "second run");
    }

    @Test
    void antiAliasingBlendsTheColoursOfAnEdgePixel() {
        // A white sphere lit by ambient light only, on the grey background: edge pixels fall between.
        Scene scene = new Scene();
        scene.addObject(new Sphere(new Vector3(0, 0, 5), 1, new Vector3(1)));
        BufferedImage image = new FastRenderer(64, 48, new SamplePattern(16)).render(scene);
        long between = 0;
        for (int y = 0; y < 48; y++) {
            for (int x = 0; x < 64; x++) {
                int red = image.getRGB(x, y) >> 16 & 0xFF;
                between += red > 25 && red < 255 ? 1 : 0;
            }
        }
        assertThat(between).as("pixels between background and sphere").isGreaterThan(20);
    }

    /**
     * Many small spheres in front of the camera, with every fifth one duplicated exactly: the
     * duplicate after it, or, {@code duplicateFirst}, before it (the tie then goes the other way).
     */
    static Scene crowd(long seed, int count, boolean duplicateFirst) {
        Random random = new Random(seed);
        Scene scene = new Scene();
        scene.setAmbientLight(new Vector3(0.2));
        scene.setPointLight(new PointLight(new Vector3(-2, 5, 0), new Vector3(1), 300));
        for (int i = 0; i < count; i++) {
            Vector3 centre = new Vector3(random.nextGaussian() * 3, random.nextGaussian() * 2,
                    4 + random.nextDouble() * 30);
            Vector3 colour = new Vector3(random.nextDouble(), random.nextDouble(), random.nextDouble());
            double radius = 0.05 + random.nextDouble() * 0.4;
            Sphere duplicate = i % 5 == 0 ? new Sphere(centre, radius, new Vector3(1).subtract(colour)) : null;
            if (duplicate != null && duplicateFirst) {
                scene.addObject(duplicate);
            }
            scene.addObject(new Sphere(centre, radius, colour));
            if (duplicate != null && !duplicateFirst) {
                scene.addObject(duplicate);
            }
        }
        return scene;
    }
}
