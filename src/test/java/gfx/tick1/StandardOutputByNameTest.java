package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.cli.MainClass;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code -o /dev/stdout} when standard output is a pipe, as in {@code tick1 -o /dev/stdout | display}:
 * the names lead through /proc/self/fd/1 to "pipe:[...]", no file of a folder, yet the PNG must
 * go into the pipe. Run in a fresh process, whose standard output is a pipe to this test.
 */
class StandardOutputByNameTest {

    @ParameterizedTest
    @ValueSource(strings = {"/dev/stdout", "/dev/fd/1"})
    void thePngGoesIntoThePipeBehindTheName(String name) throws IOException, InterruptedException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process process = new ProcessBuilder(List.of(java, "-cp", System.getProperty("java.class.path"),
                MainClass.NAME, "-i", "scenes/basic_scene.xml", "-o", name, "--width", "16", "--height", "12"))
                .redirectError(ProcessBuilder.Redirect.PIPE).start();
        byte[] png = process.getInputStream().readAllBytes();
        String err = new String(process.getErrorStream().readAllBytes());
        assertThat(process.waitFor()).as(err).isZero();
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(png));
        assertThat(image).as("a PNG on standard output; error output: %s", err).isNotNull();
        assertThat(image.getHeight()).isEqualTo(12);
        // Nothing after the PNG's last chunk: IEND, its empty data and its CRC, 0xAE426082.
        assertThat(Arrays.copyOfRange(png, png.length - 8, png.length)).as("the stream's last 8 bytes")
                .containsExactly('I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82);
    }
}
