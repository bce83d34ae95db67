package gfx.tick1.engine.image;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** The key below a heat map: it adds a strip and leaves the map's own pixels where they were. */
class HeatMapLegendTest {

    private static ImageDifference oneLevelOffAt(int width, int height, int x, int y) {
        BufferedImage expected = ImageDifferenceTest.filled(width, height, 0x808080);
        BufferedImage actual = ImageDifferenceTest.filled(width, height, 0x808080);
        actual.setRGB(x, y, 0x818080);
        return ImageDifference.between(expected, actual);
    }

    @Test
    void theLegendGoesBelowTheMapWhoseEveryPixelStaysInPlace() {
        ImageDifference difference = oneLevelOffAt(640, 480, 100, 200);
        BufferedImage map = difference.heatMap(), withLegend = difference.heatMapWithLegend();
        assertThat(withLegend.getWidth()).isEqualTo(640);
        assertThat(withLegend.getHeight()).isEqualTo(480 + HeatMapLegend.HEIGHT);
        assertThat(withLegend.getRGB(0, 0, 640, 480, null, 0, 640)).isEqualTo(map.getRGB(0, 0, 640, 480, null, 0, 640));
    }

    @Test
    void theBarRunsFromTheColourOfOneLevelToTheColourOfSixtyFour() {
        BufferedImage withLegend = oneLevelOffAt(640, 480, 0, 0).heatMapWithLegend();
        int barRow = 480 + 8;
        int[] row = withLegend.getRGB(0, barRow, 640, 1, null, 0, 640);
        int first = -1, last = -1;
        for (int x = 0; x < row.length; x++) {
            if ((row[x] & 0xFFFFFF) == ImageDifference.heatColour(1) && first < 0) {
                first = x;
            }
            if ((row[x] & 0xFFFFFF) == ImageDifference.heatColour(64)) {
                last = x;
            }
        }
        assertThat(first).as("the 1-level colour is on the bar").isNotNegative();
        assertThat(last).as("the 64-level colour comes after it").isGreaterThan(first);
        for (int levels : new int[] {2, 8, 32}) {
            assertThat(row).as("the colour of %d levels is on the bar", levels)
                    .contains(0xFF000000 | ImageDifference.heatColour(levels));
        }
    }

    @Test
    void theSignedKeyRunsFromSixtyFourDarkerDownToOneAndFromOneBrighterUpToSixtyFour() {
        BufferedImage withLegend = oneLevelOffAt(640, 480, 0, 0)
                .signedHeatMapWithLegend();
        int[] row = withLegend.getRGB(0, 480 + 8, 640, 1, null, 0, 640);
        int[] order = {indexOf(row, ImageDifference.darkerColour(64)), indexOf(row, ImageDifference.darkerColour(8)),
            indexOf(row, ImageDifference.darkerColour(1)), indexOf(row, ImageDifference.heatColour(1)),
            indexOf(row, ImageDifference.heatColour(8)), indexOf(row, ImageDifference.heatColour(64))};
        assertThat(order).as("where 64, 8 and 1 levels darker, then 1, 8 and 64 brighter, are on the bar")
                .doesNotContain(-1).isSorted();
        assertThat(inkIn(withLegend, 0, 480 + 17, 320, 10)).as("labels under the darker half").isPositive();
        assertThat(inkIn(withLegend, 320, 480 + 17, 320, 10)).as("labels under the brighter half").isPositive();
    }

    @Test
    void theSignedKeysLabelsFitTheNarrowestMapThatGetsAKey() {
        BufferedImage narrowest = oneLevelOffAt(HeatMapLegend.MIN_WIDTH, 40, 0, 0).signedHeatMapWithLegend();
        assertThat(narrowest.getHeight()).isEqualTo(40 + HeatMapLegend.HEIGHT);
        int w = HeatMapLegend.MIN_WIDTH;
        assertThat(inkIn(narrowest, 0, 40 + 17, 12, 10)).as("nothing in the left margin").isZero();
        assertThat(inkIn(narrowest, w - 12, 40 + 17, 12, 10)).as("nothing in the right margin").isZero();
    }

    private static int indexOf(int[] row, int rgb) {
        for (int x = 0; x < row.length; x++) {
            if ((row[x] & 0xFFFFFF) == rgb) {
                return x;
            }
        }
        return -1;
    }

    @Test
    void aMapTooNarrowForTheLabelsIsLeftAsItIs() {
        ImageDifference difference = oneLevelOffAt(HeatMapLegend.MIN_WIDTH - 1, 50, 3, 4);
        BufferedImage withLegend = difference.heatMapWithLegend();
        assertThat(withLegend.getHeight()).isEqualTo(50);
        int w = withLegend.getWidth();
        assertThat(withLegend.getRGB(0, 0, w, 50, null, 0, w))
                .isEqualTo(difference.heatMap().getRGB(0, 0, w, 50, null, 0, w));
    }

    @Test
    void theLegendIsTheSameForTheSameWidthWhateverTheMapShows() {
        BufferedImage one = oneLevelOffAt(400, 30, 1, 1).heatMapWithLegend();
        BufferedImage other = oneLevelOffAt(400, 300, 200, 200).heatMapWithLegend();
        assertThat(one.getRGB(0, 30, 400, HeatMapLegend.HEIGHT, null, 0, 400))
                .isEqualTo(other.getRGB(0, 300, 400, HeatMapLegend.HEIGHT, null, 0, 400));
    }

    /** The pixels of the strip that are text: the legend's light grey. */
    private static int inkIn(BufferedImage image, int x, int y, int width, int height) {
        int ink = 0;
        for (int j = y; j < y + height; j++) {
            for (int i = x; i < x + width; i++) {
                ink += (image.getRGB(i, j) & 0xFFFFFF) == 0xD0D0D0 ? 1 : 0;
            }
        }
        return ink;
    }

    @Test
    void identicalImagesGetNoDifferencesWrittenInPlaceOfTheKey() {
        BufferedImage grey = ImageDifferenceTest.filled(400, 300, 0x808080);
        BufferedImage same = ImageDifference.between(grey, grey).heatMapWithLegend();
        assertThat(same.getHeight()).isEqualTo(300 + HeatMapLegend.HEIGHT);
        int[] strip = same.getRGB(0, 300, 400, HeatMapLegend.HEIGHT, null, 0, 400);
        assertThat(strip).as("no colour of the key: nothing differs").doesNotContain(
                0xFF000000 | ImageDifference.heatColour(1), 0xFF000000 | ImageDifference.heatColour(64));
        assertThat(inkIn(same, 0, 300, 400, HeatMapLegend.HEIGHT)).as("the words NO DIFFERENCES").isPositive();
        assertThat(strip).isNotEqualTo(oneLevelOffAt(400, 300, 5, 5).heatMapWithLegend()
                .getRGB(0, 300, 400, HeatMapLegend.HEIGHT, null, 0, 400));
    }

    /** Every tick label's top row is inked over at least two cells, as the top of a digit should be. */
    @Test
    void theOneOfTheKeyStartsOnItsTopRowLikeTheOtherDigits() {
        BufferedImage withLegend = oneLevelOffAt(640, 480, 0, 0).heatMapWithLegend();
        int labelTop = 480 + 17;
        // The 1 is centred under the bar's start (x = 12): its glyph spans x 9 to 14.
        assertThat(inkIn(withLegend, 9, labelTop, 6, 2)).as("the 1's top row").isGreaterThanOrEqualTo(8);
    }
}
