package gfx.tick1.command.bench;

import gfx.tick1.engine.image.PngOutput;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.knowm.xchart.AnnotationText;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.XYStyler;

/**
 * The benchmark's plot, speed-vs-error.png: time per frame (log scale) against RMS error in
 * levels, one point per variant. Times are comparable only for the same scene and frame size,
 * and errors only against the same reference image, so each frame size and reference gets a panel
 * of its own, one above the other. Within a panel every variant
 * has a number, a colour and a shape of its own; its marker is filled when it rendered on every
 * core and hollow on one thread, and its number stands above (or below) it; points that fall on
 * one another share a label that names them all ("5, 6"). Each axis runs a tenth of its
 * range past the outermost points, so that no marker touches the frame.
 */
final class BenchChart {

    /** Twelve colours that stay apart from one another on white (and for most colour-blind readers). */
    static final Color[] COLOURS = {
        new Color(0x1F77B4), new Color(0xFF7F0E), new Color(0x2CA02C), new Color(0xD62728),
        new Color(0x9467BD), new Color(0x8C564B), new Color(0xE377C2), new Color(0x7F7F7F),
        new Color(0xBCBD22), new Color(0x17BECF), new Color(0x000000), new Color(0xAEC7E8)};

    /** The share of each axis's range left empty beyond the outermost points. */
    static final double PADDING = 0.1;

    /** The least range of the time axis, as a ratio, so that a panel of close times has ticks to read. */
    static final double LEAST_TIME_RATIO = 4;

    /** The least range of the error axis, in levels, so that a panel of errors of 0 has one. */
    static final double LEAST_ERROR_RANGE = 1;

    private static final int WIDTH = 1000;
    private static final int PANEL_HEIGHT = 560;
    private static final int MARKER_SIZE = 11;
    /** The height of the row of time labels below the frame, in pixels. */
    private static final int TIME_LABELS_HEIGHT = 24;

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
     * number of spheres is what the panel shows; tick1.xml's variants have one of their own. An
     * error is comparable only with errors against the same reference, so variants measured against
     * another (anti-aliased ones against a 256-sample image, the others against the exact image)
     * have a panel of their own too, whose title names the reference.
     */
    private static String panelTitle(Result r) {
        String scene = r.scene().startsWith("crowd") ? "crowds of spheres" : r.scene();
        return String.format(Locale.ROOT, "%s at %d x %d, error against %s", scene, r.width(), r.height(),
                reference(r.errorAgainst()));
    }

    /** What an error was measured against, in words: the report's short names spelt out. */
    static String reference(String errorAgainst) {
        return switch (errorAgainst) {
            case "truth" -> "the exact image";
            case "brute force" -> "the brute-force image";
            default -> errorAgainst.endsWith(" samples") ? "a " + errorAgainst.replace(" samples", "-sample") + " image"
                    : errorAgainst;
        };
    }

    private static XYChart panel(String title, List<Result> rows) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(PANEL_HEIGHT).title("tick1 bench: " + title)
                .xAxisTitle("time per frame, ms (log scale)").yAxisTitle("RMS error, levels").build();
        axes(chart, rows);
        for (int i = 0; i < rows.size(); i++) {
            Result r = rows.get(i);
            String label = String.format(Locale.ROOT, "%d  %s, %d thread%s%s", i + 1, r.variant(), r.threads(),
                    r.threads() == 1 ? "" : "s", r.scene().startsWith("crowd") ? ", " + r.scene() : "");
            XYSeries series = chart.addSeries(label, new double[] {r.timing().median()}, new double[] {r.rmsError()});
            series.setMarker(new PlotMarker(PlotMarker.Glyph.values()[i % PlotMarker.Glyph.values().length],
                    r.threads() > 1));
            series.setMarkerColor(COLOURS[i % COLOURS.length]);
        }
        annotate(chart, rows);
        return chart;
    }

    /** Both axes' ranges, padded, and their tick labels: 1-2-5 steps of milliseconds, and levels from 0. */
    private static void axes(XYChart chart, List<Result> rows) {
        XYStyler styler = chart.getStyler();
        styler.setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        styler.setLegendPosition(Styler.LegendPosition.OutsideE);
        styler.setMarkerSize(MARKER_SIZE);
        styler.setAnnotationTextFont(styler.getAxisTickLabelsFont());
        styler.setAnnotationTextFontColor(styler.getAxisTickLabelsColor());
        // The axis ranges are the padding: the points' range fills the frame.
        styler.setPlotContentSize(1.0);
        double[] time = timeRange(rows.stream().mapToDouble(r -> r.timing().median()).toArray());
        double[] error = errorRange(rows.stream().mapToDouble(Result::rmsError).toArray());
        // XChart draws a grid line at every multiple of a power of ten but labels only the powers,
        // and a label formatter would make the axis linear: its labels are drawn by timeLabels.
        styler.setXAxisLogarithmic(true);
        styler.setXAxisTicksVisible(false);
        styler.setAxisTitlePadding(TIME_LABELS_HEIGHT);
        styler.setXAxisMin(time[0]);
        styler.setXAxisMax(time[1]);
        styler.setYAxisMin(error[0]);
        styler.setYAxisMax(error[1]);
        chart.setCustomYAxisTickLabelsFormatter(BenchChart::levels);
    }

    /** The time axis: the times' range, at least {@link #LEAST_TIME_RATIO} wide, padded on a log scale. */
    static double[] timeRange(double[] millis) {
        double low = Math.log10(Math.max(1e-6, Arrays.stream(millis).min().orElse(1)));
        double high = Math.log10(Math.max(1e-6, Arrays.stream(millis).max().orElse(1)));
        double widen = Math.max(0, Math.log10(LEAST_TIME_RATIO) - (high - low)) / 2;
        low -= widen;
        high += widen;
        double pad = PADDING * (high - low);
        return new double[] {Math.pow(10, low - pad), Math.pow(10, high + pad)};
    }

    /** The error axis: the errors' range, at least {@link #LEAST_ERROR_RANGE} high, padded. */
    static double[] errorRange(double[] levels) {
        double low = Arrays.stream(levels).min().orElse(0);
        double high = Math.max(Arrays.stream(levels).max().orElse(0), low + LEAST_ERROR_RANGE);
        double pad = PADDING * (high - low);
        return new double[] {low - pad, high + pad};
    }

    /** An error tick's label: blank below 0 (no error is negative; the axis runs there only as padding). */
    private static String levels(double value) {
        if (Math.abs(value) < 1e-9) {
            return "0";
        }
        return value < 0 ? "" : new BigDecimal(value).round(new MathContext(4)).stripTrailingZeros().toPlainString();
    }

    /**
     * Writes the time axis's labels below the frame, and each point's number above its marker, one
     * label for points that fall on one another.
     */
    private static void annotate(XYChart chart, List<Result> rows) {
        BitmapEncoder.getBufferedImage(chart);   // lays the chart out, so that values map to pixels
        XYStyler styler = chart.getStyler();
        int below = (int) Math.round(chart.getScreenYFromChart(styler.getYAxisMin()) + TIME_LABELS_HEIGHT / 2.0);
        for (double millis : new LogTicks(styler.getXAxisMin(), styler.getXAxisMax()).labelled()) {
            chart.addAnnotation(new AnnotationText(LogTicks.text(millis), millis, chart.getChartYFromCoordinate(below),
                    false));
        }
        List<PointLabels.Point> points = new ArrayList<>();
        for (int i = 0; i < rows.size(); i++) {
            Result r = rows.get(i);
            points.add(new PointLabels.Point(i + 1, chart.getScreenXFromChart(r.timing().median()),
                    chart.getScreenYFromChart(r.rmsError())));
        }
        for (PointLabels.Label label : new PointLabels(MARKER_SIZE).of(points)) {
            chart.addAnnotation(new AnnotationText(label.text(), chart.getChartXFromCoordinate((int) label.x()),
                    chart.getChartYFromCoordinate((int) label.y()), false));
        }
    }
}
