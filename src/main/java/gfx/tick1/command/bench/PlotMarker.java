package gfx.tick1.command.bench;

import java.awt.BasicStroke;
import java.awt.Graphics2D;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import org.knowm.xchart.style.markers.Marker;

/**
 * A point's marker on the benchmark's plot: one of ten shapes, filled, or hollow (an outline) so
 * that a marker drawn over another leaves the one below visible.
 */
final class PlotMarker extends Marker {

    /** The shapes, each unlike the others at 11 pixels. */
    enum Glyph { CIRCLE, SQUARE, DIAMOND, TRIANGLE_UP, TRIANGLE_DOWN, TRIANGLE_LEFT, TRIANGLE_RIGHT, PENTAGON,
        HEXAGON, STAR }

    private static final BasicStroke OUTLINE = new BasicStroke(2f);

    private final Glyph glyph;
    private final boolean filled;

    PlotMarker(Glyph glyph, boolean filled) {
        this.glyph = glyph;
        this.filled = filled;
    }

    Glyph glyph() {
        return glyph;
    }

    boolean filled() {
        return filled;
    }

    @Override
    public void paint(Graphics2D g, double x, double y, int size) {
        Shape shape = shape(x, y, filled ? size : size - 1);
        if (filled) {
            g.fill(shape);
        } else {
            g.setStroke(OUTLINE);
            g.draw(shape);
        }
    }

    private Shape shape(double x, double y, double size) {
        double r = size / 2;
        return switch (glyph) {
            case CIRCLE -> new Ellipse2D.Double(x - r, y - r, size, size);
            case SQUARE -> new Rectangle2D.Double(x - 0.9 * r, y - 0.9 * r, 1.8 * r, 1.8 * r);
            case DIAMOND -> polygon(x, y, 1.15 * r, 4, 0);
            case TRIANGLE_UP -> polygon(x, y, 1.1 * r, 3, 0);
            case TRIANGLE_DOWN -> polygon(x, y, 1.1 * r, 3, Math.PI);
            case TRIANGLE_LEFT -> polygon(x, y, 1.1 * r, 3, -Math.PI / 2);
            case TRIANGLE_RIGHT -> polygon(x, y, 1.1 * r, 3, Math.PI / 2);
            case PENTAGON -> polygon(x, y, 1.05 * r, 5, 0);
            case HEXAGON -> polygon(x, y, r, 6, Math.PI / 6);
            case STAR -> star(x, y, 1.2 * r);
        };
    }

    /** A regular polygon of {@code corners} about (x, y), its first corner straight up, turned by {@code turn}. */
    private static Path2D polygon(double x, double y, double radius, int corners, double turn) {
        return outline(x, y, corners, turn, radius, radius);
    }

    /** A five-pointed star: its corners alternately at the radius and at 0.45 of it. */
    private static Path2D star(double x, double y, double radius) {
        return outline(x, y, 10, 0, radius, 0.45 * radius);
    }

    /** Corners evenly round (x, y), the even ones at {@code radius} and the odd ones at {@code inner}. */
    private static Path2D outline(double x, double y, int corners, double turn, double radius, double inner) {
        Path2D path = new Path2D.Double();
        for (int i = 0; i < corners; i++) {
            double angle = turn + 2 * Math.PI * i / corners;
            double reach = i % 2 == 0 ? radius : inner;
            double px = x + reach * Math.sin(angle);
            double py = y - reach * Math.cos(angle);
            if (i == 0) {
                path.moveTo(px, py);
            } else {
                path.lineTo(px, py);
            }
        }
        path.closePath();
        return path;
    }
}
