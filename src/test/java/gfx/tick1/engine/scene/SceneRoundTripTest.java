package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.math.Vector3;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.LongStream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Property: any scene within the documented bounds, written out as a scene file in any of the
 * ways the format allows, loads back exactly, number for number and colour for colour.
 * Each case is generated from its seed, so a failure names a reproducible scene.
 */
class SceneRoundTripTest {

    @TempDir
    Path dir;

    static LongStream seeds() {
        return LongStream.range(0, 300);
    }

    /** A colour as written (#RRGGBB) and as loaded (channel / 255.0). */
    record Colour(int rgb) {
        Vector3 value() {
            return new Vector3((rgb >> 16 & 0xFF) / 255.0, (rgb >> 8 & 0xFF) / 255.0, (rgb & 0xFF) / 255.0);
        }
    }

    record GeneratedSphere(double x, double y, double z, double radius, Colour colour) {
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void aGeneratedSceneLoadsBackExactly(long seed) throws IOException {
        Random random = new Random(seed);
        Colour ambient = random.nextBoolean() ? new Colour(random.nextInt(1 << 24)) : null;
        double[] light = {number(random), number(random), number(random), Math.abs(number(random))};
        Colour lightColour = new Colour(random.nextInt(1 << 24));
        List<GeneratedSphere> spheres = new ArrayList<>();
        for (int i = random.nextInt(6); i > 0; i--) {
            double radius = Math.abs(number(random));
            spheres.add(new GeneratedSphere(number(random), number(random), number(random),
                    radius == 0 ? 1 : radius, new Colour(random.nextInt(1 << 24))));
        }

        StringBuilder xml = new StringBuilder(
                random.nextBoolean() ? "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" : "");
        xml.append("<scene>\n");
        if (ambient != null) {
            xml.append(element(random, "ambient-light", "colour", hex(random, ambient)));
        }
        xml.append(element(random, "point-light", "x", text(random, light[0]), "y", text(random, light[1]),
                "z", text(random, light[2]), "intensity", text(random, light[3]), "colour", hex(random, lightColour)));
        for (GeneratedSphere s : spheres) {
            xml.append(element(random, "sphere", "x", text(random, s.x()), "y", text(random, s.y()),
                    "z", text(random, s.z()), "radius", text(random, s.radius()), "colour", hex(random, s.colour())));
        }
        xml.append("</scene>\n");
        Path file = dir.resolve("scene.xml");
        Files.writeString(file, xml, StandardCharsets.UTF_8);

        SceneLoader loader = new SceneLoader(file, true);

        Scene scene = loader.getScene();
        assertThat(loader.getWarnings()).as(xml.toString()).isEmpty();
        assertThat(scene.getAmbientLighting()).as(xml.toString())
                .isEqualTo(ambient == null ? Scene.DEFAULT_AMBIENT : ambient.value());
        PointLight loadedLight = scene.getPointLight();
        assertThat(loadedLight.getPosition()).as(xml.toString()).isEqualTo(new Vector3(light[0], light[1], light[2]));
        assertThat(loadedLight.getIntensity()).as(xml.toString()).isEqualTo(light[3]);
        assertThat(loadedLight.getColour()).as(xml.toString()).isEqualTo(lightColour.value());
        assertThat(scene.getObjects()).as(xml.toString()).hasSameSizeAs(spheres);
        for (int i = 0; i < spheres.size(); i++) {
            Sphere loaded = scene.getObjects().get(i);
            GeneratedSphere expected = spheres.get(i);
            assertThat(SphereGeometry.centre(loaded)).as(xml.toString())
                    .isEqualTo(new Vector3(expected.x(), expected.y(), expected.z()));
            assertThat(SphereGeometry.radius(loaded)).as(xml.toString()).isEqualTo(expected.radius());
            assertThat(loaded.getColour()).as(xml.toString()).isEqualTo(expected.colour().value());
        }
    }

    /** A number within the bound: small integers, ordinary decimals, or anything up to the bound. */
    private static double number(Random random) {
        double bound = SceneLoader.MAX_MAGNITUDE;
        return switch (random.nextInt(4)) {
            case 0 -> random.nextInt(21) - 10;
            case 1 -> Math.round((random.nextDouble() * 20 - 10) * 1000) / 1000.0;
            case 2 -> (random.nextDouble() * 2 - 1) * bound;
            default -> (random.nextDouble() * 2 - 1) * Math.pow(10, random.nextInt(40) - 30);
        };
    }

    /**
     * The number as a person or a program might write it: Java's shortest round-tripping form
     * (which uses E notation for large and small numbers), or %.17g, which also reads back exactly,
     * with optional spaces and sign. Both parse back to the same double.
     */
    private static String text(Random random, double value) {
        String written = random.nextBoolean() ? Double.toString(value)
                : String.format(java.util.Locale.ROOT, "%.17g", value).trim();
        if (value >= 0 && random.nextInt(4) == 0) {
            written = "+" + written;
        }
        return random.nextInt(4) == 0 ? " " + written + " " : written;
    }

    private static String hex(Random random, Colour colour) {
        String text = String.format("#%06X", colour.rgb());
        return random.nextBoolean() ? text : text.toLowerCase();
    }

    /** An element with its attributes in a random order and random quotes. */
    private static String element(Random random, String name, String... attributes) {
        List<String> pairs = new ArrayList<>();
        for (int i = 0; i < attributes.length; i += 2) {
            char quote = random.nextBoolean() ? '"' : '\'';
            pairs.add(attributes[i] + "=" + quote + attributes[i + 1] + quote);
        }
        java.util.Collections.shuffle(pairs, random);
        return "  <" + name + " " + String.join(random.nextBoolean() ? " " : "\n    ", pairs) + "/>\n";
    }
}
