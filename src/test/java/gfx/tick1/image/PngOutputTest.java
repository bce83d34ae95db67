package gfx.tick1.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PngOutputTest {

    @TempDir
    Path dir;

    private static BufferedImage image() {
        BufferedImage image = new BufferedImage(3, 2, BufferedImage.TYPE_INT_RGB);
        image.setRGB(1, 1, 0xABCDEF);
        return image;
    }

    @Test
    void writtenPngDecodesToTheSamePixels() throws IOException {
        Path target = dir.resolve("a.png");
        PngOutput.write(image(), target);
        assertThat(ImageIO.read(target.toFile()).getRGB(1, 1) & 0xFFFFFF).isEqualTo(0xABCDEF);
    }

    @Test
    void replacesAnExistingFileAndLeavesNoTemporaryFile() throws IOException {
        Path target = dir.resolve("a.png");
        Files.writeString(target, "old");
        PngOutput.write(image(), target);
        assertThat(ImageIO.read(target.toFile())).isNotNull();
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files).containsExactly(target);
        }
    }

    @Test
    void aMissingDirectoryIsReportedAndNothingIsCreated() {
        Path target = dir.resolve("missing").resolve("a.png");
        assertThatThrownBy(() -> PngOutput.write(image(), target)).isInstanceOf(IOException.class)
                .hasMessageContaining("does not exist");
        assertThat(dir.resolve("missing")).doesNotExist();
    }
}
