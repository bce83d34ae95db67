package gfx.tick1.image;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.Random;
import java.util.zip.Adler32;
import java.util.zip.Deflater;
import javax.imageio.ImageIO;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class PngEncoderTest {

    private static BufferedImage noisyGradient(int width, int height, long seed) {
        Random random = new Random(seed);
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int r = (x * 255 / Math.max(1, width - 1)) ^ (random.nextInt(4));
                int g = y * 255 / Math.max(1, height - 1);
                int b = random.nextInt(256);
                image.setRGB(x, y, r << 16 | g << 8 | b);
            }
        }
        return image;
    }

    @ParameterizedTest(name = "{0} x {1}, level {2}")
    @CsvSource({"1, 1, 1", "3, 2, 1", "640, 480, 1", "17, 200, 1", "200, 129, 6", "64, 64, 0", "99, 65, -1", "31, 130, 2"})
    void everyReaderDecodesTheFileToExactlyTheImagesPixels(int width, int height, int level) throws IOException {
        int deflateLevel = level == -1 ? Deflater.HUFFMAN_ONLY : level;
        BufferedImage image = noisyGradient(width, height, width * 31L + height);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PngEncoder.write(image, out, deflateLevel);

        BufferedImage decoded = ImageIO.read(new ByteArrayInputStream(out.toByteArray()));
        assertThat(decoded).as("ImageIO could not read the PNG").isNotNull();
        ImageDifference difference = ImageDifference.between(image, decoded);
        assertThat(difference.differingPixels()).as(difference.summary()).isZero();
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void adlerChecksumsOfTwoPartsCombineIntoTheChecksumOfTheWhole(long seed) {
        Random random = new Random(seed);
        byte[] data = new byte[random.nextInt(300_000)];
        random.nextBytes(data);
        int split = data.length == 0 ? 0 : random.nextInt(data.length);
        Adler32 whole = new Adler32(), first = new Adler32(), second = new Adler32();
        whole.update(data);
        first.update(data, 0, split);
        second.update(data, split, data.length - split);
        assertThat(PngEncoder.combineAdler32(first.getValue(), second.getValue(), data.length - split))
                .isEqualTo(whole.getValue());
    }
}
