package gfx.tick1.engine.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

class ImageDifferenceTest {

    /** An image of one colour; the heat map's legend tests use it too. */
    static BufferedImage filled(int width, int height, int rgb) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, rgb);
            }
        }
        return image;
    }

    @Test
    void equalImagesHaveNoDifferenceAndInfinitePsnr() {
        ImageDifference d = ImageDifference.between(filled(4, 3, 0x123456), filled(4, 3, 0x123456));
        assertThat(d.differingPixels()).isZero();
        assertThat(d.psnr()).isInfinite();
        assertThat(d.boundingBox()).isEqualTo("none");
        assertThat(d.shareWithin(0)).isEqualTo(1.0);
    }

    @Test
    void theSummaryOfOnePixelOneLevelOffSaysSoInTheSingular() {
        BufferedImage actual = filled(4, 1, 0x101010);
        actual.setRGB(2, 0, 0x101011);
        assertThat(ImageDifference.between(filled(4, 1, 0x101010), actual).summary()).as("the summary")
                .startsWith("1 of 4 pixels differs (25.000%), max difference 1 level (R 0, G 0, B 1)");
    }

    @Test
    void theSummaryOfSeveralPixelsSaysSoInThePlural() {
        BufferedImage actual = filled(4, 1, 0x131313);
        assertThat(ImageDifference.between(filled(4, 1, 0x101010), actual).summary()).as("the summary")
                .startsWith("4 of 4 pixels differ (100.000%), max difference 3 levels (R 3, G 3, B 3)");
    }

    @Test
    void countsPixelsByTheirWorstChannel() {
        BufferedImage expected = filled(4, 1, 0x101010);
        BufferedImage actual = filled(4, 1, 0x101010);
        actual.setRGB(1, 0, 0x111010); // 1 level in red
        actual.setRGB(3, 0, 0x101013); // 3 levels in blue
        ImageDifference d = ImageDifference.between(expected, actual);
        assertThat(d.differingPixels()).isEqualTo(2);
        assertThat(d.pixelsWithin(0)).isEqualTo(2);
        assertThat(d.pixelsWithin(1)).isEqualTo(3);
        assertThat(d.pixelsWithin(3)).isEqualTo(4);
        assertThat(d.maxPerChannel()).containsExactly(1, 0, 3);
        assertThat(d.isWithin(2)).isFalse();
        assertThat(d.isWithin(3)).isTrue();
        assertThat(d.boundingBox()).isEqualTo("1,0 - 3,0");
        assertThat(d.meanDifference()).isEqualTo(4 / 12.0);
    }

    @Test
    void psnrOfAUniformOneLevelErrorIsFortyEightDecibels() {
        // MSE = 1: PSNR = 10 log10(255^2) = 48.13 dB.
        ImageDifference d = ImageDifference.between(filled(5, 5, 0x202020), filled(5, 5, 0x212121));
        assertThat(d.psnr()).isCloseTo(48.13, org.assertj.core.data.Offset.offset(0.01));
    }

    @Test
    void sizesMustAgree() {
        assertThatThrownBy(() -> ImageDifference.between(filled(4, 3, 0), filled(3, 4, 0)))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("image sizes differ: expected 4 x 3, actual 3 x 4");
    }

    @Test
    void heatMapMarksExactlyTheDifferingPixels() {
        BufferedImage expected = filled(3, 3, 0x808080);
        BufferedImage actual = filled(3, 3, 0x808080);
        actual.setRGB(2, 1, 0x818080);
        BufferedImage map = ImageDifference.between(expected, actual).heatMap();
        for (int y = 0; y < 3; y++) {
            for (int x = 0; x < 3; x++) {
                int red = map.getRGB(x, y) >> 16 & 0xFF, green = map.getRGB(x, y) >> 8 & 0xFF;
                boolean marked = red > green;
                assertThat(marked).as("pixel %d,%d", x, y).isEqualTo(x == 2 && y == 1);
            }
        }
    }

    @Test
    void heatColoursRunFromDarkRedAtOneLevelToYellowWhiteFromSixtyFourLevels() {
        assertThat(ImageDifference.heatColour(1)).isEqualTo(0x800000);
        assertThat(ImageDifference.heatColour(64)).isEqualTo(0xFFFFA0);
        assertThat(ImageDifference.heatColour(255)).isEqualTo(0xFFFFA0);
        for (int levels = 2; levels <= 64; levels++) {
            int brighter = ImageDifference.heatColour(levels), dimmer = ImageDifference.heatColour(levels - 1);
            int sum = (brighter >> 16) + (brighter >> 8 & 0xFF) + (brighter & 0xFF);
            int sumBefore = (dimmer >> 16) + (dimmer >> 8 & 0xFF) + (dimmer & 0xFF);
            assertThat(sum).as("%d levels against %d", levels, levels - 1).isGreaterThan(sumBefore);
        }
        assertThatThrownBy(() -> ImageDifference.heatColour(0)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void theSignedHeatMapPaintsABrighterPixelInTheHeatColoursAndADarkerOneInTheDarkerColours() {
        BufferedImage expected = filled(1, 1, 0x808080);
        for (int levels : new int[] {1, 5, 64, 127}) {
            BufferedImage brighter = ImageDifference.between(expected, filled(1, 1, 0x808080 + levels)).signedHeatMap();
            BufferedImage darker = ImageDifference.between(expected, filled(1, 1, 0x808080 - levels)).signedHeatMap();
            assertThat(brighter.getRGB(0, 0) & 0xFFFFFF).as("%d levels brighter", levels)
                    .isEqualTo(ImageDifference.heatColour(levels));
            assertThat(darker.getRGB(0, 0) & 0xFFFFFF).as("%d levels darker", levels)
                    .isEqualTo(ImageDifference.darkerColour(levels));
        }
    }

    @Test
    void aPixelIsBrighterWhenItsChannelsAddUpToMoreAndOtherwiseAsItsWorstChannelSays() {
        BufferedImage expected = filled(3, 1, 0x808080);
        BufferedImage actual = filled(3, 1, 0x808080);
        actual.setRGB(0, 0, 0x8A7D7D);   // red +10, green and blue -3 each: more light in all, though two are darker
        actual.setRGB(1, 0, 0x788098);   // red -8, blue +24: more light in all
        actual.setRGB(2, 0, 0x768A80);   // red -10, green +10: the same light in all; red comes first of the two worst
        BufferedImage map = ImageDifference.between(expected, actual).signedHeatMap();
        assertThat(map.getRGB(0, 0) & 0xFFFFFF).as("more light in all").isEqualTo(ImageDifference.heatColour(10));
        assertThat(map.getRGB(1, 0) & 0xFFFFFF).as("more light in all").isEqualTo(ImageDifference.heatColour(24));
        assertThat(map.getRGB(2, 0) & 0xFFFFFF).as("the same light: the worst channel, red, is darker")
                .isEqualTo(ImageDifference.darkerColour(10));
    }

    @Test
    void darkerColoursAreTheHeatColoursWithRedAndBlueExchangedFromDarkBlueToPaleCyan() {
        assertThat(ImageDifference.darkerColour(1)).isEqualTo(0x000080);
        assertThat(ImageDifference.darkerColour(64)).isEqualTo(0xA0FFFF);
        for (int levels = 1; levels <= 255; levels++) {
            int warm = ImageDifference.heatColour(levels);
            assertThat(ImageDifference.darkerColour(levels)).as("%d levels", levels)
                    .isEqualTo((warm & 0xFF) << 16 | warm & 0xFF00 | warm >> 16);
        }
    }

    @Test
    void theHeatMapPaintsADifferingPixelInItsHeatColour() {
        BufferedImage expected = filled(1, 1, 0x808080);
        for (int levels : new int[] {1, 5, 64, 127}) {
            BufferedImage map = ImageDifference.between(expected, filled(1, 1, 0x808080 + levels)).heatMap();
            assertThat(map.getRGB(0, 0) & 0xFFFFFF).as("%d levels", levels)
                    .isEqualTo(ImageDifference.heatColour(levels));
        }
    }
}
