package gfx.tick1.engine.image;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import javax.imageio.ImageIO;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Image formats known by their bytes, whatever a file is called, and by a name's extension. */
class ImageFormatTest {

    private static byte[] encoded(String format) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        assertThat(ImageIO.write(new BufferedImage(4, 3, BufferedImage.TYPE_INT_RGB), format, out)).isTrue();
        return out.toByteArray();
    }

    @ParameterizedTest
    @CsvSource({"png, PNG", "jpeg, JPEG", "gif, GIF", "bmp, BMP", "tiff, TIFF_BIG_ENDIAN"})
    void whatJavaWritesInAFormatIsKnownAsThatFormatByItsBytes(String writer, ImageFormat format)
            throws IOException {
        assertThat(ImageFormat.of(encoded(writer))).contains(format);
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "<scene/>", "RIFF\u0000\u0000\u0000\u0000WAVE"})
    void otherBytesAreNoImageFormat(String start) {
        assertThat(ImageFormat.of(start.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1))).isEmpty();
    }

    @ParameterizedTest
    @CsvSource({"out.jpg, JPEG", "OUT.JPEG, JPEG", "a.b/c.webp, WEBP", "render.png, PNG"})
    void anExtensionNamesItsFormatInAnyCase(String name, ImageFormat format) {
        assertThat(ImageFormat.ofName(name)).contains(format);
    }

    @ParameterizedTest
    @ValueSource(strings = {"/tmp/tmp.aB3xYz", "-", "/dev/stdout", "out"})
    void aNameOfNoImageFormatHasNone(String name) {
        assertThat(ImageFormat.ofName(name)).isEmpty();
    }
}
