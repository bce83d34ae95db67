package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Loading from bytes in memory (the previewer's uploads) behaves as loading a file of that name. */
class SceneLoaderInMemoryTest {

    @TempDir
    Path dir;

    private Path file(String xml) throws IOException {
        return Files.writeString(dir.resolve("scene.xml"), xml);
    }

    @Test
    void readsTheSameSceneWithTheSameWarningsAsTheFile() throws IOException {
        String xml = "<scene>\n  <sphere x=\"1\" z=\"4\" colour=\"#102030\" shiny=\"yes\"/>\n</scene>\n";
        Path file = file(xml);
        SceneLoader fromFile = new SceneLoader(file, false);
        SceneLoader inMemory = new SceneLoader(file.toString(), xml.getBytes(StandardCharsets.UTF_8), false);

        assertThat(inMemory.getWarnings()).isNotEmpty().isEqualTo(fromFile.getWarnings());
        assertThat(inMemory.getScene().getObjects()).hasSize(1);
        Sphere read = inMemory.getScene().getObjects().get(0), expected = fromFile.getScene().getObjects().get(0);
        assertThat(SphereGeometry.centre(read)).isEqualTo(SphereGeometry.centre(expected));
        assertThat(SphereGeometry.radius(read)).isEqualTo(SphereGeometry.radius(expected));
        assertThat(read.getColour()).isEqualTo(expected.getColour());
    }

    @Test
    void rejectsABadSceneWithTheSameMessageAsTheFile() throws IOException {
        String xml = "<scene>\n  <sphere radius=\"0\" colour=\"#FF0000\"/>\n</scene>\n";
        Path file = file(xml);
        String fromFile = catchMessage(() -> new SceneLoader(file, false));

        assertThatThrownBy(() -> new SceneLoader(file.toString(), xml.getBytes(StandardCharsets.UTF_8), false))
                .isInstanceOf(SceneException.class).hasMessage(fromFile);
    }

    @Test
    void refusesMoreThanTheFileSizeLimit() {
        byte[] tooLarge = new byte[(int) SceneLoader.MAX_FILE_BYTES + 1];
        assertThatThrownBy(() -> new SceneLoader("big.xml", tooLarge, false))
                .isInstanceOf(SceneException.class)
                .hasMessage("big.xml: file is " + tooLarge.length + " bytes, expected at most "
                        + SceneLoader.MAX_FILE_BYTES + " (64 MiB)");
    }

    private static String catchMessage(Runnable load) {
        try {
            load.run();
        } catch (SceneException e) {
            return e.getMessage();
        }
        throw new AssertionError("expected a SceneException");
    }
}
