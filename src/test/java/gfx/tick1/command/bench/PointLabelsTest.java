package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The numbers beside the plot's points: each point named once, and no label over another. */
class PointLabelsTest {

    private static final double MARKER = 11;

    @Test
    void pointsOnTopOfOneAnotherShareOneLabelThatNamesThemAll() {
        List<PointLabels.Label> labels = new PointLabels(MARKER).of(List.of(new PointLabels.Point(1, 300, 200),
                new PointLabels.Point(2, 100, 200), new PointLabels.Point(3, 101, 201)));
        assertThat(labels).extracting(PointLabels.Label::text).containsExactly("2, 3", "1");
    }

    @Test
    void aPointFarFromTheOthersHasItsOwnLabelJustAboveIt() {
        PointLabels.Label label = new PointLabels(MARKER).of(List.of(new PointLabels.Point(7, 100, 200))).get(0);
        assertThat(label.text()).isEqualTo("7");
        assertThat(label.x()).isEqualTo(100);
        assertThat(label.y() + label.height() / 2).isLessThanOrEqualTo(200 - MARKER / 2).isGreaterThan(180);
    }

    /** On crowded random plots: each number in one label, no two labels overlapping, none over another's marker. */
    @Test
    void everyPointIsNamedOnceAndNoLabelCoversAnotherLabelOrMarker() {
        SplittableRandom random = new SplittableRandom(8);
        for (int plot = 0; plot < 500; plot++) {
            List<PointLabels.Point> points = new ArrayList<>();
            for (int i = 1; i <= 1 + random.nextInt(14); i++) {
                points.add(new PointLabels.Point(i, random.nextDouble(0, 300), random.nextDouble(0, 120)));
            }
            List<PointLabels.Label> labels = new PointLabels(MARKER).of(points);
            List<Integer> named = labels.stream().flatMap(l -> Arrays.stream(l.text().split(", ")))
                    .map(Integer::valueOf).sorted().toList();
            assertThat(named).as("numbers named on %s", points)
                    .isEqualTo(points.stream().map(PointLabels.Point::number).toList());
            for (PointLabels.Label a : labels) {
                for (PointLabels.Label b : labels) {
                    if (a != b) {
                        assertThat(a.overlaps(b.x() - b.width() / 2, b.y() - b.height() / 2, b.x() + b.width() / 2,
                                b.y() + b.height() / 2)).as("%s over %s", a, b).isFalse();
                    }
                }
                for (PointLabels.Point p : points) {
                    boolean own = Arrays.asList(a.text().split(", ")).contains(String.valueOf(p.number()));
                    if (!own) {
                        assertThat(a.overlaps(p.x() - MARKER / 2, p.y() - MARKER / 2, p.x() + MARKER / 2,
                                p.y() + MARKER / 2)).as("%s over marker %s", a, p).isFalse();
                    }
                }
            }
        }
    }
}
