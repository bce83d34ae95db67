package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.image.ImageDifference;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.XYStyler;

/**
 * The benchmark's plot: no two points look alike, no panel mixes frame sizes, and every point
 * stands inside its frame on axes that can be read.
 */
class BenchChartTest {

    /** The rows of a full run: eleven variants of tick1.xml at 4K, and the crowds at 640 x 480. */
    private static List<Result> fullRun() {
        List<Result> results = new ArrayList<>();
        for (int i = 0; i < 11; i++) {
            results.add(result("variant " + i, "tick1.xml", 3840, 2160, i + 1));
        }
        for (String crowd : new String[] {"crowd-1000.xml", "crowd-10000.xml"}) {
            results.add(result("brute force", crowd, 640, 480, 200));
            results.add(result("BVH", crowd, 640, 480, 70));
        }
        return results;
    }

    private static Result result(String variant, String scene, int width, int height, double millis) {
        return result(variant, scene, width, height, millis, 2, 0);
    }

    /** A result whose image is {@code wrongLevels} off in one channel of one pixel of 16. */
    private static Result result(String variant, String scene, int width, int height, double millis, int threads,
            int wrongLevels) {
        BufferedImage image = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        BufferedImage other = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        other.setRGB(0, 0, wrongLevels);
        return new Result(variant, scene, width, height, 1, threads, Timing.of(new double[] {millis}), "truth",
                ImageDifference.between(image, other), 4, 4);
    }

    /** A quick run's rows: close times, errors from 0 to a few levels, one and two threads. */
    private static List<Result> quickRun() {
        List<Result> results = new ArrayList<>();
        double[] millis = {47, 10.7, 21.7, 7.1, 29.6, 110, 16.4, 16.3, 49, 28.4};
        int[] wrong = {1, 1, 1, 1, 20, 9, 1, 1, 1, 1};
        for (int i = 0; i < millis.length; i++) {
            results.add(result("variant " + i, "tick1.xml", 640, 480, millis[i], i % 3 == 1 ? 1 : 2, wrong[i]));
        }
        results.add(result("brute force", "crowd-1000.xml", 640, 480, 633, 2, 0));
        results.add(result("BVH", "crowd-1000.xml", 640, 480, 124, 2, 0));
        return results;
    }

    /** Where a value lies along an axis from min to max, 0 at min and 1 at max. */
    private static double along(double value, double min, double max, boolean logarithmic) {
        return logarithmic ? Math.log(value / min) / Math.log(max / min) : (value - min) / (max - min);
    }

    /**
     * Every point stands clear of its panel's frame by a tenth of the points' range or more,
     * also where all of a panel's errors are 0 or its times lie close together.
     */
    @Test
    void everyPointStandsClearOfItsPanelsFrame() {
        for (List<Result> run : List.of(fullRun(), quickRun())) {
            for (XYChart panel : BenchChart.panels(run, false)) {
                XYStyler styler = panel.getStyler();
                assertThat(styler.getXAxisMin()).as("time axis of %s", panel.getTitle()).isNotNull().isPositive();
                assertThat(styler.getYAxisMin()).as("error axis of %s", panel.getTitle()).isNotNull();
                for (XYSeries series : panel.getSeriesMap().values()) {
                    double x = along(series.getXData()[0], styler.getXAxisMin(), styler.getXAxisMax(), true);
                    double y = along(series.getYData()[0], styler.getYAxisMin(), styler.getYAxisMax(), false);
                    assertThat(x).as("%s: %s across the time axis", panel.getTitle(), series.getName())
                            .isBetween(0.08, 0.92);
                    assertThat(y).as("%s: %s up the error axis", panel.getTitle(), series.getName())
                            .isBetween(0.08, 0.92);
                }
            }
        }
    }

    @Test
    void theTimeAxisOfEveryPanelSpansAtLeastAFactorOfFourAndHasThreeLabelledTicks() {
        for (List<Result> run : List.of(fullRun(), quickRun())) {
            for (XYChart panel : BenchChart.panels(run, false)) {
                XYStyler styler = panel.getStyler();
                assertThat(styler.getXAxisMax() / styler.getXAxisMin()).as(panel.getTitle())
                        .isGreaterThanOrEqualTo(BenchChart.LEAST_TIME_RATIO);
                assertThat(new LogTicks(styler.getXAxisMin(), styler.getXAxisMax()).labelled())
                        .as(panel.getTitle()).hasSizeGreaterThanOrEqualTo(3);
            }
        }
    }

    @Test
    void aMarkerIsFilledOnEveryCoreAndHollowOnOneThread() {
        List<Result> run = quickRun();
        XYChart panel = BenchChart.panels(run, false).get(0);
        List<XYSeries> series = new ArrayList<>(panel.getSeriesMap().values());
        for (int i = 0; i < series.size(); i++) {
            assertThat(((PlotMarker) series.get(i).getMarker()).filled()).as(series.get(i).getName())
                    .isEqualTo(run.get(i).threads() > 1);
        }
    }

    @Test
    void eachLegendEntryStartsWithTheNumberWrittenBesideItsPoint() {
        for (XYChart panel : BenchChart.panels(quickRun(), false)) {
            int number = 1;
            for (String name : panel.getSeriesMap().keySet()) {
                assertThat(name).startsWith(number++ + "  ");
            }
        }
    }

    @Test
    void everySeriesOfAPanelHasAColourAndAMarkerOfItsOwn() {
        for (XYChart panel : BenchChart.panels(fullRun(), false)) {
            List<XYSeries> series = new ArrayList<>(panel.getSeriesMap().values());
            assertThat(series.stream().map(XYSeries::getMarkerColor).collect(Collectors.toList()))
                    .as("marker colours of %s", panel.getTitle()).doesNotHaveDuplicates();
            int shapes = PlotMarker.Glyph.values().length;
            List<XYSeries> firstTen = series.subList(0, Math.min(series.size(), shapes));
            assertThat(firstTen.stream().map(s -> ((PlotMarker) s.getMarker()).glyph()).collect(Collectors.toList()))
                    .as("marker shapes of %s", panel.getTitle()).doesNotHaveDuplicates();
        }
    }

    /**
     * Errors measured against different images are not on one axis: anti-aliased variants, measured against a
     * 256-sample image, are plotted apart from the others, measured against the exact image, and each panel's title
     * names its reference.
     */
    @Test
    void variantsMeasuredAgainstAnotherReferenceHaveAPanelOfTheirOwnThatNamesIt() {
        BufferedImage image = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        List<Result> results = List.of(
                new Result("one sample", "tick1.xml", 640, 480, 1, 2, Timing.of(new double[] {10}), "truth",
                        ImageDifference.between(image, image), 4, 4),
                new Result("4 samples", "tick1.xml", 640, 480, 4, 2, Timing.of(new double[] {40}), "256 samples",
                        ImageDifference.between(image, image), 4, 4),
                new Result("another sample", "tick1.xml", 640, 480, 1, 1, Timing.of(new double[] {20}), "truth",
                        ImageDifference.between(image, image), 4, 4));

        List<XYChart> panels = BenchChart.panels(results, true);

        assertThat(panels).extracting(XYChart::getTitle).containsExactly(
                "tick1 bench: tick1.xml at 640 x 480, error against the exact image (quick run)",
                "tick1 bench: tick1.xml at 640 x 480, error against a 256-sample image (quick run)");
        assertThat(panels.get(0).getSeriesMap()).as("the variants against the exact image").hasSize(2);
        assertThat(panels.get(1).getSeriesMap().keySet()).as("the variant against 256 samples")
                .singleElement().asString().contains("4 samples");
    }

    @Test
    void eachFrameSizeHasAPanelOfItsOwn() {
        List<XYChart> panels = BenchChart.panels(fullRun(), false);
        assertThat(panels).extracting(XYChart::getTitle)
                .containsExactly("tick1 bench: tick1.xml at 3840 x 2160, error against the exact image",
                        "tick1 bench: crowds of spheres at 640 x 480, error against the exact image");
        assertThat(panels.get(0).getSeriesMap()).hasSize(11);
        assertThat(panels.get(1).getSeriesMap().keySet())
                .allMatch(label -> label.endsWith("crowd-1000.xml") || label.endsWith("crowd-10000.xml"));
    }

}
