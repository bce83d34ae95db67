package gfx.tick1.bench;

import gfx.tick1.image.PngOutput;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The benchmark's plot, speed-vs-error.png: time per frame (log scale) against RMS error in
 * levels, one point per variant. Times are comparable only for the same scene and frame size, so
 * each frame size gets a panel of its own, one above the other; within a panel every variant has
 * a colour of its own and a marker of its own, so that no two points can be confused.
 */
final class BenchChart {

    /** Twelve colours that stay apart from one another on white (and for most colour-blind readers). */
    static final Color[] COLOURS = {
        new Color(0x1F77B4), new Color(0xFF7F0E), new Color(0x2CA02C), new Color(0xD62728),
        new Color(0x9467BD), new Color(0x8C564B), new Color(0xE377C2), new Color(0x7F7F7F),
        new Color(0xBCBD22), new Color(0x17BECF), new Color(0x000000), new Color(0xAEC7E8)};

    /** Every marker XChart draws, so that the first ten variants of a panel all have different shapes. */
    static final Marker[] MARKERS = {
        SeriesMarkers.CIRCLE, SeriesMarkers.DIAMOND, SeriesMarkers.SQUARE, SeriesMarkers.TRIANGLE_UP,
        SeriesMarkers.TRIANGLE_DOWN, SeriesMarkers.CROSS, SeriesMarkers.PLUS, SeriesMarkers.TRAPEZOID,
        SeriesMarkers.OVAL, SeriesMarkers.RECTANGLE};

    private static final int WIDTH = 1000;
    private static final int PANEL_HEIGHT = 560;

    private BenchChart() {
    }

    /** One chart per scene and frame size, in the order the results first name them. */
    static List<XYChart> panels(List<Result> results, boolean quick) {
        Map<String, List<Result>> byFrame = new LinkedHashMap<>();
        for (Result r : results) {
            byFrame.computeIfAbsent(panelTitle(r), title -> new ArrayList<>()).add(r);
        }
        List<XYChart> panels = new ArrayList<>();
        byFrame.forEach((title, rows) -> panels.add(panel(title + (quick ? " (quick run)" : ""), rows)));
        return panels;
    }

    /** The panels one above the other, written as a PNG. */
    static void write(List<Result> results, boolean quick, Path file) throws IOException {
        List<BufferedImage> images = new ArrayList<>();
        for (XYChart panel : panels(results, quick)) {
            images.add(BitmapEncoder.getBufferedImage(panel));
        }
        int height = images.stream().mapToInt(BufferedImage::getHeight).sum();
        BufferedImage plot = new BufferedImage(WIDTH, Math.max(1, height), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = plot.createGraphics();
        int y = 0;
        for (BufferedImage image : images) {
            g.drawImage(image, 0, y, null);
            y += image.getHeight();
        }
        g.dispose();
        PngOutput.write(plot, file);
    }

    /**
     * The crowds share a panel: they are rendered at the same size, and their time against the
     * number of spheres is what the panel shows; tick1.xml's variants have one of their own.
     */
    private static String panelTitle(Result r) {
        String scene = r.scene().startsWith("crowd") ? "crowds of spheres" : r.scene();
        return String.format(Locale.ROOT, "%s at %d x %d", scene, r.width(), r.height());
    }

    private static XYChart panel(String title, List<Result> rows) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(PANEL_HEIGHT).title("tick1 bench: " + title)
                .xAxisTitle("time per frame, ms (log scale)").yAxisTitle("RMS error, levels").build();
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setMarkerSize(11);
        for (int i = 0; i < rows.size(); i++) {
            Result r = rows.get(i);
            String label = String.format(Locale.ROOT, "%s, %d thread%s%s", r.variant(), r.threads(),
                    r.threads() == 1 ? "" : "s", r.scene().startsWith("crowd") ? ", " + r.scene() : "");
            XYSeries series = chart.addSeries(label, new double[] {r.timing().median()}, new double[] {r.rmsError()});
            series.setMarker(MARKERS[i % MARKERS.length]);
            series.setMarkerColor(COLOURS[i % COLOURS.length]);
        }
        return chart;
    }
}
