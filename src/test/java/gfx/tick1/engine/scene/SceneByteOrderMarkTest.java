package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A scene saved with a UTF-8 byte-order mark, as Windows editors save it, has its errors at the line and column
 * of the same scene saved without one: the mark is no character of line 1.
 */
class SceneByteOrderMarkTest {

    private static final byte[] MARK = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};

    private static String messageOf(byte[] bytes) {
        try {
            new SceneLoader("scene.xml", bytes, false);
        } catch (SceneException e) {
            return e.getMessage();
        }
        throw new AssertionError("expected the scene to be refused");
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"<scene><bogus/></scene>", "<scene><sphere radius='x' colour='#FF0000'/></scene>",
        "<scene><sphere</scene>"})
    void anErrorOnLineOneIsAtTheSameColumnWithAByteOrderMark(String xml) {
        byte[] plain = xml.getBytes(StandardCharsets.UTF_8);
        byte[] marked = new byte[MARK.length + plain.length];
        System.arraycopy(MARK, 0, marked, 0, MARK.length);
        System.arraycopy(plain, 0, marked, MARK.length, plain.length);

        assertThat(messageOf(marked)).as("the error of the scene saved with a byte-order mark")
                .isEqualTo(messageOf(plain)).startsWith("scene.xml:1:");
    }
}
