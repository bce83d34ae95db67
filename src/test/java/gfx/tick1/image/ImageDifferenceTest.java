package gfx.tick1.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

class ImageDifferenceTest {

    private static BufferedImage filled(int width, int height, int rgb) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, rgb);
            }
        }
        return image;
    }

    @Test
    void identicalImagesHaveNoDifferenceAndInfinitePsnr() {
        ImageDifference d = ImageDifference.between(filled(4, 3, 0x123456), filled(4, 3, 0x123456));
        assertThat(d.differingPixels()).isZero();
        assertThat(d.maxDifference()).isZero();
        assertThat(d.psnr()).isInfinite();
        assertThat(d.boundingBox()).isEqualTo("none");
    }

    @Test
    void countsDifferingPixelsAndTheLargestDifferencePerChannel() {
        BufferedImage actual = filled(4, 3, 0x101010);
        actual.setRGB(1, 2, 0x131010);
        actual.setRGB(3, 0, 0x10100A);
        ImageDifference d = ImageDifference.between(filled(4, 3, 0x101010), actual);
        assertThat(d.differingPixels()).isEqualTo(2);
        assertThat(d.maxPerChannel()).containsExactly(3, 0, 6);
        assertThat(d.maxDifference()).isEqualTo(6);
        assertThat(d.meanPerChannel()[2]).isCloseTo(6 / 12.0, within(1e-12));
        assertThat(d.boundingBox()).isEqualTo("1,0 - 3,2");
    }

    @Test
    void psnrOfAUniformOneLevelErrorIsAbout48Decibels() {
        ImageDifference d = ImageDifference.between(filled(8, 8, 0x808080), filled(8, 8, 0x818181));
        assertThat(d.psnr()).isCloseTo(20 * Math.log10(255), within(1e-9));
    }

    @Test
    void imagesOfDifferentSizesAreRefusedWithBothSizes() {
        assertThatThrownBy(() -> ImageDifference.between(filled(4, 3, 0), filled(3, 4, 0)))
                .hasMessage("image sizes differ: expected 4 x 3, actual 3 x 4");
    }

    @Test
    void heatMapMarksEveryDifferingPixelAndDimsTheRest() {
        BufferedImage actual = filled(4, 3, 0xFFFFFF);
        actual.setRGB(2, 1, 0xFFFFFE);
        BufferedImage map = ImageDifference.between(filled(4, 3, 0xFFFFFF), actual).heatMap();
        assertThat(map.getRGB(2, 1) >> 16 & 0xFF).as("a one-level error is still clearly red").isGreaterThan(100);
        assertThat(map.getRGB(0, 0) & 0xFFFFFF).as("unchanged pixels are a dim grey").isEqualTo(0x3F3F3F);
    }
}
