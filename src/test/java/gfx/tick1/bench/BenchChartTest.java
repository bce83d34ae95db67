package gfx.tick1.bench;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.image.ImageDifference;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;

/** The benchmark's plot: no two points look alike, and no panel mixes frame sizes. */
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
        BufferedImage image = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        return new Result(variant, scene, width, height, 1, 2, Timing.of(new double[] {millis}), "truth",
                ImageDifference.between(image, image), 4, 4);
    }

    @Test
    void everySeriesOfAPanelHasAColourAndAMarkerOfItsOwn() {
        for (XYChart panel : BenchChart.panels(fullRun(), false)) {
            List<XYSeries> series = new ArrayList<>(panel.getSeriesMap().values());
            assertThat(series.stream().map(XYSeries::getMarkerColor).collect(Collectors.toList()))
                    .as("marker colours of %s", panel.getTitle()).doesNotHaveDuplicates();
            List<XYSeries> firstTen = series.subList(0, Math.min(series.size(), BenchChart.MARKERS.length));
            assertThat(firstTen.stream().map(s -> s.getMarker().getClass()).collect(Collectors.toList()))
                    .as("marker shapes of %s", panel.getTitle()).doesNotHaveDuplicates();
        }
    }

    @Test
    void eachFrameSizeHasAPanelOfItsOwn() {
        List<XYChart> panels = BenchChart.panels(fullRun(), false);
        assertThat(panels).extracting(XYChart::getTitle)
                .containsExactly("tick1 bench: tick1.xml at 3840 x 2160",
                        "tick1 bench: crowds of spheres at 640 x 480");
        assertThat(panels.get(0).getSeriesMap()).hasSize(11);
        assertThat(panels.get(1).getSeriesMap().keySet())
                .allMatch(label -> label.endsWith("crowd-1000.xml") || label.endsWith("crowd-10000.xml"));
    }

}
