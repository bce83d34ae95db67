package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gfx.tick1.engine.math.Vector3;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

class SceneLoaderTest {

    @TempDir
    Path dir;

    private Path file(String xml) throws IOException {
        Path path = dir.resolve("scene.xml");
        Files.writeString(path, xml, StandardCharsets.UTF_8);
        return path;
    }

    private Scene load(String xml) throws IOException {
        return new SceneLoader(file(xml).toString()).getScene();
    }

    /** The error message with the temporary directory taken off the front. */
    private String errorFor(String xml) throws IOException {
        Path path = file(xml);
        try {
            new SceneLoader(path, false);
        } catch (SceneException e) {
            return e.getMessage().replace(path.toString(), "scene.xml");
        }
        throw new AssertionError("expected " + xml + " to be rejected");
    }

    @Test
    void readsTheHandoutsTaskScene() throws IOException {
        Scene scene = new SceneLoader(Path.of("scenes/tick1.xml"), false).getScene();
        assertThat(scene.getAmbientLighting()).isEqualTo(new Vector3(0x55 / 255.0));
        assertThat(scene.getPointLight().getPosition()).isEqualTo(new Vector3(1, 3, 2));
        assertThat(scene.getPointLight().getColour()).isEqualTo(new Vector3(0xB3 / 255.0, 0xDD / 255.0, 1));
        assertThat(scene.getPointLight().getIntensity()).isEqualTo(120);
        assertThat(scene.getObjects()).hasSize(2);
        Sphere first = scene.getObjects().get(0);
        assertThat(SphereGeometry.centre(first)).isEqualTo(new Vector3(0.55, -0.16, 3.5));
        assertThat(SphereGeometry.radius(first)).isEqualTo(0.5);
        assertThat(first.getColour()).isEqualTo(new Vector3(0, 0x71 / 255.0, 0xBC / 255.0));
    }

    @Test
    void missingCoordinatesRadiusAndIntensityTakeTheStarterDefaults() throws IOException {
        Scene scene = load("<scene><point-light colour='#FFFFFF'/><sphere colour='#FF0000'/></scene>");
        Sphere sphere = scene.getObjects().get(0);
        assertThat(SphereGeometry.centre(sphere)).isEqualTo(new Vector3(0));
        assertThat(SphereGeometry.radius(sphere)).isEqualTo(1);
        assertThat(scene.getPointLight().getPosition()).isEqualTo(new Vector3(0));
        assertThat(scene.getPointLight().getIntensity()).isEqualTo(100);
    }

    @Test
    void withoutAnAmbientLightElementTheAmbientLightIsWhite() throws IOException {
        assertThat(load("<scene/>").getAmbientLighting()).isEqualTo(new Vector3(1));
    }

    @Test
    void ofSeveralPointLightsTheLastIsUsedWithAWarning() throws IOException {
        Path path = file("<scene>\n<point-light x='1' colour='#FFFFFF'/>\n"
                + "<point-light x='2' colour='#FFFFFF'/>\n</scene>");
        SceneLoader loader = new SceneLoader(path, false);
        assertThat(loader.getScene().getPointLight().getPosition().x).isEqualTo(2);
        assertThat(loader.getWarnings()).containsExactly(path + ":3:1: warning: another <point-light>: Tick 1 "
                + "models one light, the last one in the file is used");
    }

    @Test
    void strictModeTurnsWarningsIntoErrors() throws IOException {
        Path path = file("<scene>\n<point-light colour='#FFFFFF'/><point-light colour='#FFFFFF'/></scene>");
        assertThatThrownBy(() -> new SceneLoader(path, true)).isInstanceOf(SceneException.class)
                .hasMessage(path + ":2:32: another <point-light>: Tick 1 models one light, the last one in the "
                                + "file is used (an error under --strict)");
    }

    @Test
    void elementsNestedAtAnyDepthAreReadInDocumentOrder() throws IOException {
        Scene scene = load("<scene><sphere colour='#FF0000'><sphere x='1' colour='#00FF00'/></sphere>"
                + "<point-light colour='#FFFFFF'/></scene>");
        assertThat(scene.getObjects()).extracting(s -> SphereGeometry.centre(s).x).containsExactly(0.0, 1.0);
    }

    @Test
    void numbersMayHaveSignsExponentsAndSurroundingSpace() throws IOException {
        Sphere sphere = load("<scene><point-light colour='#FFFFFF'/>"
                + "<sphere x=' -1.5 ' y='+2' z='3e1' radius='.5' colour='#ff00AA'/></scene>").getObjects().get(0);
        assertThat(SphereGeometry.centre(sphere)).isEqualTo(new Vector3(-1.5, 2, 30));
        assertThat(SphereGeometry.radius(sphere)).isEqualTo(0.5);
        assertThat(sphere.getColour()).isEqualTo(new Vector3(1, 0, 0xAA / 255.0));
    }

    static Stream<Arguments> badInputs() {
        return Stream.of(
                Arguments.of("wrong root", "<world/>",
                        "scene.xml:1:1: root element <world>: expected <scene>"),
                Arguments.of("unknown element", "<scene>\n  <plane colour='#FFFFFF'/></scene>",
                        "scene.xml:2:3: unknown element <plane>: expected sphere, ambient-light or point-light"),
                Arguments.of("missing colour", "<scene><sphere x='1'/></scene>",
                        "scene.xml:1:8: sphere has no colour: expected colour=\"#RRGGBB\""),
                Arguments.of("short colour", "<scene><sphere colour='#FFF'/></scene>",
                        "scene.xml:1:16: sphere colour \"#FFF\": "
                                + "must be # followed by six hexadecimal digits, as in #FF8800"),
                Arguments.of("colour without hash", "<scene><ambient-light colour='FF0000'/></scene>",
                        "scene.xml:1:23: ambient-light colour \"FF0000\": "
                                + "must be # followed by six hexadecimal digits, as in #FF8800"),
                Arguments.of("non-hex colour", "<scene><sphere colour='#GG0000'/></scene>",
                        "scene.xml:1:16: sphere colour \"#GG0000\": "
                                + "must be # followed by six hexadecimal digits, as in #FF8800"),
                Arguments.of("unparsable number", "<scene><sphere x='1,5' colour='#FF0000'/></scene>",
                        "scene.xml:1:16: sphere x \"1,5\": must be a decimal number such as 1.5 or -2e3"),
                Arguments.of("empty number", "<scene><sphere y='' colour='#FF0000'/></scene>",
                        "scene.xml:1:16: sphere y \"\": must be a decimal number such as 1.5 or -2e3"),
                Arguments.of("not a number", "<scene><sphere z='NaN' colour='#FF0000'/></scene>",
                        "scene.xml:1:16: sphere z \"NaN\": must be a finite decimal number"),
                Arguments.of("infinity", "<scene><sphere z='-Infinity' colour='#FF0000'/></scene>",
                        "scene.xml:1:16: sphere z \"-Infinity\": must be a finite decimal number"),
                Arguments.of("overflowing number", "<scene><sphere z='1e400' colour='#FF0000'/></scene>",
                        "scene.xml:1:16: sphere z \"1e400\": "
                                + "must be a number between -1e16 and 1e16 (the range the renderer is tested for)"),
                Arguments.of("hexadecimal number", "<scene><sphere z='0x10' colour='#FF0000'/></scene>",
                        "scene.xml:1:16: sphere z \"0x10\": must be a decimal number such as 1.5 or -2e3"),
                Arguments.of("zero radius", "<scene><sphere radius='0' colour='#FF0000'/></scene>",
                        "scene.xml:1:16: sphere radius \"0\": must be a number greater than 0"),
                Arguments.of("negative radius", "<scene><sphere radius='-1' colour='#FF0000'/></scene>",
                        "scene.xml:1:16: sphere radius \"-1\": must be a number greater than 0"),
                Arguments.of("negative intensity", "<scene><point-light intensity='-5' colour='#FF0000'/></scene>",
                        "scene.xml:1:21: point-light intensity \"-5\": must be a number of at least 0"),
                Arguments.of("truncated XML", "<scene><sphere colour='#FF0000'/>",
                        "scene.xml:1:34: malformed XML: the file ends in the middle of the scene "
                                + "(a tag, comment or element is left open), expected it to end with </scene>"),
                Arguments.of("DOCTYPE", "<!DOCTYPE scene [<!ENTITY x 'y'>]><scene/>",
                        "scene.xml:1:10: DOCTYPE declaration: "
                                + "not allowed in scene files (no DTDs or entities), expected <scene>"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badInputs")
    void rejectsBadInputWithOneLineNamingFileLineAndColumn(String what, String xml, String expected)
            throws IOException {
        assertThat(errorFor(xml)).isEqualTo(expected);
    }

    @Test
    void aMissingFileIsNamedInTheError() {
        Path missing = dir.resolve("nowhere.xml");
        assertThatThrownBy(() -> new SceneLoader(missing, false)).isInstanceOf(SceneException.class)
                .hasMessage(missing + ": no such file");
    }

    @Test
    void aDirectoryIsNotAScene() {
        assertThatThrownBy(() -> new SceneLoader(dir, false))
                .hasMessage(dir + ": is a directory, expected a scene file");
    }

    @Test
    void anEmptyFileIsRejected() throws IOException {
        assertThat(errorFor("")).isEqualTo("scene.xml: file is empty, expected a <scene> element");
    }

    @Test
    void anUnknownAttributeIsAWarningNamingWhatIsExpected() throws IOException {
        Path path = file("<scene><point-light colour='#FFFFFF'/><sphere raduis='2' colour='#FF0000'/></scene>");
        assertThat(new SceneLoader(path, false).getWarnings()).containsExactly(path + ":1:47: warning: sphere "
                + "attribute \"raduis\": not part of Tick 1 scenes, ignored (expected colour, radius, x, y, z); did "
                + "you mean radius? radius is not given, so the default 1 is used");
    }

    @Test
    void aMisspeltAttributeOfAnElementThatHasTheRightOneGetsNoSuggestion() throws IOException {
        Path path = file("<scene><point-light colour='#FFFFFF'/><sphere radius='2' raduis='2' colour='#F00000'/>"
                + "</scene>");
        assertThat(new SceneLoader(path, false).getWarnings()).singleElement().asString()
                .endsWith("(expected colour, radius, x, y, z)");
    }

    @Test
    void colourSpeltTheAmericanWayIsNamedInTheError() throws IOException {
        assertThat(errorFor("<scene><ambient-light color='#555555'/></scene>")).isEqualTo("scene.xml:1:8: "
                + "ambient-light has no colour: expected colour=\"#RRGGBB\" (the tick spells it colour, not color)");
    }

    @Test
    void unknownAttributesAreWarnedOfInTheOrderTheFileGivesThem() throws IOException {
        Path path = file("<scene><point-light colour='#FFFFFF'/><sphere zeta='1' colour='#FF0000' alpha='2'/></scene>");
        assertThat(new SceneLoader(path, false).getWarnings()).extracting(w -> w.replace(path.toString(), ""))
                .containsExactly(":1:47: warning: sphere attribute \"zeta\": not part of Tick 1 scenes, ignored "
                                + "(expected colour, radius, x, y, z)",
                        ":1:73: warning: sphere attribute \"alpha\": not part of Tick 1 scenes, ignored "
                                + "(expected colour, radius, x, y, z)");
    }

    @Test
    void anUnknownAttributeAfterAValueHoldingAGreaterThanSignIsNamedWhereItIs() throws IOException {
        Path path = file("<scene><point-light colour='#FFFFFF'/>\n"
                + "  <sphere colour='#FF0000' note='a>b' zeta='1'/></scene>");
        assertThat(new SceneLoader(path, false).getWarnings()).extracting(w -> w.replace(path.toString(), ""))
                .containsExactly(":2:28: warning: sphere attribute \"note\": not part of Tick 1 scenes, ignored "
                                + "(expected colour, radius, x, y, z)",
                        ":2:39: warning: sphere attribute \"zeta\": not part of Tick 1 scenes, ignored "
                                + "(expected colour, radius, x, y, z)");
    }

    @Test
    void aProblemBeforeMalformedXmlIsTheOneReported() throws IOException {
        assertThat(errorFor("<scene>\n<sphere radius='-1' colour='#FF0000'/>\n<sphere colour='#FF0000'>\n"))
                .isEqualTo("scene.xml:2:9: sphere radius \"-1\": must be a number greater than 0");
    }

    @Test
    void malformedXmlBeforeAnyProblemIsTheOneReported() throws IOException {
        assertThat(errorFor("<scene>\n<sphere colour='#FF0000'>\n</scene>\n<sphere radius='-1'/>\n"))
                .startsWith("scene.xml:3:3: malformed XML: ");
    }

    @Test
    void aSceneWithoutAPointLightIsLitByAmbientLightWithAWarning() throws IOException {
        Path path = file("<scene><sphere colour='#FF0000'/></scene>");
        SceneLoader loader = new SceneLoader(path, false);
        assertThat(loader.getScene().getPointLight()).isNull();
        assertThat(loader.getWarnings()).containsExactly(path
                + ": warning: no <point-light>: the spheres are lit by the ambient light only");
    }
}
