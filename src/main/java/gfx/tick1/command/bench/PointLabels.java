package gfx.tick1.command.bench;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The numbers written beside the plot's markers, which name each point's entry in the legend.
 * Each point gets its number just above its marker, or just below where the label above would run
 * into another; points whose markers touch, or whose labels meet both ways, share one label that
 * lists their numbers ("3, 7"), so that a point hidden under another is still counted and named.
 * Positions are in pixels, y growing downwards.
 */
final class PointLabels {

    /** A marker's number and where it is drawn. */
    record Point(int number, double x, double y) {
    }

    /** A label: its text, centred at (x, y), and the box it takes. */
    record Label(String text, double x, double y, double width, double height) {

        boolean overlaps(double left, double top, double right, double bottom) {
            return x - width / 2 < right && x + width / 2 > left && y - height / 2 < bottom && y + height / 2 > top;
        }
    }

    /** How wide a character of a label is, and how tall a label, at the plot's annotation font. */
    static final double CHARACTER_WIDTH = 7;
    static final double LABEL_HEIGHT = 13;

    private final double markerSize;

    PointLabels(double markerSize) {
        this.markerSize = markerSize;
    }

    /** Points that share a label, and whether it stands below them rather than above. */
    private static final class Group {
        final List<Point> points = new ArrayList<>();
        boolean below;

        Group(Point point) {
            points.add(point);
        }
    }

    /** The labels of these points: every point is named by exactly one, and no two labels overlap. */
    List<Label> of(List<Point> points) {
        List<Group> groups = new ArrayList<>();
        points.forEach(point -> groups.add(new Group(point)));
        for (int[] pair = clashing(groups); pair != null; pair = clashing(groups)) {
            Group a = groups.get(pair[0]);
            Group b = groups.get(pair[1]);
            if (!b.below && movesBelowClear(b, groups)) {
                b.below = true;
            } else if (!a.below && movesBelowClear(a, groups)) {
                a.below = true;
            } else {
                a.points.addAll(b.points);
                a.below = false;
                groups.remove(b);
            }
        }
        return groups.stream().map(this::label).sorted(Comparator.comparingDouble(Label::x)).toList();
    }

    /** The indices of two groups that clash, or null. */
    private int[] clashing(List<Group> groups) {
        for (int i = 0; i < groups.size(); i++) {
            for (int j = i + 1; j < groups.size(); j++) {
                if (clash(groups.get(i), groups.get(j))) {
                    return new int[] {i, j};
                }
            }
        }
        return null;
    }

    /** Whether the group's label, moved below its markers, would clash with no other group. */
    private boolean movesBelowClear(Group group, List<Group> groups) {
        group.below = true;
        boolean clear = groups.stream().noneMatch(other -> other != group && clash(group, other));
        group.below = false;
        return clear;
    }

    /** Whether two groups must not stand as they are: their markers touch, or a label meets the other's. */
    private boolean clash(Group a, Group b) {
        Label labelA = label(a);
        Label labelB = label(b);
        double reach = markerSize / 2 + 2;
        for (Point p : a.points) {
            for (Point q : b.points) {
                if (Math.abs(p.x() - q.x()) < 2 * reach && Math.abs(p.y() - q.y()) < 2 * reach) {
                    return true;
                }
            }
        }
        return labelA.overlaps(labelB.x() - labelB.width() / 2 - 2, labelB.y() - labelB.height() / 2,
                labelB.x() + labelB.width() / 2 + 2, labelB.y() + labelB.height() / 2)
                || covers(labelA, b.points, reach) || covers(labelB, a.points, reach);
    }

    private static boolean covers(Label label, List<Point> points, double reach) {
        return points.stream().anyMatch(p -> label.overlaps(p.x() - reach, p.y() - reach, p.x() + reach,
                p.y() + reach));
    }

    /** The group's label: its numbers in order, centred over (or under) the group, just clear of its markers. */
    private Label label(Group group) {
        String text = group.points.stream().map(Point::number).sorted().map(String::valueOf)
                .collect(Collectors.joining(", "));
        double x = group.points.stream().mapToDouble(Point::x).average().orElse(0);
        double gap = markerSize / 2 + 3 + LABEL_HEIGHT / 2;
        double y = group.below ? group.points.stream().mapToDouble(Point::y).max().orElse(0) + gap
                : group.points.stream().mapToDouble(Point::y).min().orElse(0) - gap;
        return new Label(text, x, y, CHARACTER_WIDTH * text.length() + 4, LABEL_HEIGHT);
    }
}
