package gfx.tick1.command.coverage;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.coverage.CatalogueOnScenes;
import gfx.tick1.command.shared.coverage.Coverage;
import gfx.tick1.command.shared.coverage.NamedScene;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * For each of several mistakes, a scene built to show it is counted as catching it, and a scene
 * built not to is not: the count is of the pixels that really differ, not of a list kept by hand.
 */
class CatalogueOnScenesTest {

    private static final String WHITE_SPHERE = scene("#333333", "#FFFFFF", "#FFFFFF", 1);
    private static final String RED_SPHERE = scene("#333333", "#FFFFFF", "#E03020", 1);

    /** One sphere of radius {@code radius} in front of the camera, lit from the upper right. */
    private static String scene(String ambient, String light, String sphere, double radius) {
        return "<scene><ambient-light colour=\"" + ambient + "\"/><point-light x=\"3\" y=\"3\" z=\"3\" colour=\""
                + light + "\" intensity=\"100\"/><sphere x=\"0\" y=\"0\" z=\"6\" radius=\"" + radius
                + "\" colour=\"" + sphere + "\"/></scene>";
    }

    static Stream<Arguments> mistakesWithScenesThatShowThemAndScenesThatDoNot() {
        return Stream.of(
                Arguments.of(Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT, file("scenes/hard/camera-inside-sphere.xml"),
                        bundled(BundledScenes.TICK1)),
                Arguments.of(Variant.DISTANCE_ALWAYS_S1, file("scenes/hard/camera-inside-sphere.xml"),
                        bundled(BundledScenes.HIDDEN)),
                Arguments.of(Variant.ROOTS_ACCEPTED_AT_ZERO,
                        file("src/test/resources/scenes/sphere-through-camera.xml"),
                        bundled(BundledScenes.TICK1)),
                Arguments.of(Variant.NORMAL_NOT_NORMALISED, text(scene("#333333", "#FFFFFF", "#E03020", 0.7)),
                        text(RED_SPHERE)),
                Arguments.of(Variant.HIGHLIGHT_COLOURED, text(RED_SPHERE), text(WHITE_SPHERE)),
                Arguments.of(Variant.DIFFUSE_WITHOUT_C_DIFF, text(RED_SPHERE), text(WHITE_SPHERE)),
                Arguments.of(Variant.AMBIENT_WITHOUT_C_DIFF, text(RED_SPHERE), text(WHITE_SPHERE)),
                Arguments.of(Variant.NO_AMBIENT, text(RED_SPHERE), text(scene("#000000", "#FFFFFF", "#E03020", 1))),
                Arguments.of(Variant.RED_BLUE_SWAPPED, text(RED_SPHERE), text(scene("#333333", "#FFFFFF", "#808080",
                        1))));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("mistakesWithScenesThatShowThemAndScenesThatDoNot")
    void aSceneBuiltToShowAMistakeCatchesItAndOneBuiltNotToDoesNot(Variant mistake, Scene shows, Scene hides) {
        Coverage coverage = CatalogueOnScenes.measure(List.of(new NamedScene("shows", shows),
                new NamedScene("hides", hides)), 160, 120);
        assertThat(coverage.of(mistake).pixels().get(0)).as("%s on the scene built to show it", mistake)
                .isPositive();
        assertThat(coverage.of(mistake).pixels().get(1)).as("%s on the scene built not to", mistake).isZero();
    }

    private static Scene file(String path) {
        return new SceneLoader(Path.of(path), false).getScene();
    }

    private static Scene bundled(String name) {
        return BundledScenes.load(name);
    }

    private static Scene text(String xml) {
        return new SceneLoader("built.xml", xml.getBytes(StandardCharsets.UTF_8), true).getScene();
    }
}
