package gfx.tick1.command.shared.grader.report;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The index's year at a glance: findings counted by students, a note at a pass never as a failure. */
class YearAtAGlanceTest {

    private static final String FACT = "your illuminate gives negative diffuse light when N.L < 0";
    private static final String UNTESTED = "a mistake not tested by the course's scenes: for a ray that grazes a sphere"
            + " (from (0, 0, 0) along (0, 0, 1), sphere at (0, 1, 5) of radius 1), your intersectionWith returns"
            + " a hit at s = 0.2";

    private static StudentResult result(String id, boolean passed, List<String> lines, Findings found, long millis) {
        return new StudentResult(new Submission("S" + id + "_" + id + "_assignsubmission_file_", id, "S" + id, null,
                null, null), new StudentResult.Summary(passed, passed ? 1 : 0, 1, passed ? Category.Outcome.PASSED
                : new Category.Mistake("illuminate: N.L not clamped"), ""), List.of(new SceneResult("tick1.xml", false,
                        passed, lines, SceneResult.Images.NONE)), Duration.ofMillis(millis), found);
    }

    private static final List<StudentResult> COHORT = List.of(
            result("1", false, List.of("behaviour: " + FACT, "reread: handout section 5, Figure 6(b)."),
                    new Findings(null, List.of(FACT), List.of(), List.of(),
                            List.of("handout section 5, Figure 6(b).")), 800),
            result("2", false, List.of("verdict: far root: every pixel matches its render of tick1.xml exactly.",
                    "reread: handout section 4, steps 4 and 5."),
                    new Findings(Variant.FAR_ROOT, List.of(), List.of(UNTESTED), List.of(),
                            List.of("handout section 4, steps 4 and 5.")), 2_000),
            result("3", true, List.of("note: " + FACT
                    + " (tick1.xml and the hidden scene do not show this; handout section 5)"),
                    new Findings(null, List.of(FACT), List.of(), List.of(), List.of()), 70_000));

    @Test
    void aFindingIsCountedAmongTheFailedAndAFindingAtAPassAmongThePassed() {
        assertThat(YearAtAGlance.html(COHORT, List.of("0.00", "0.00", "1.00")))
                .as("the findings' row").contains("<tr><td>" + Html.escape(FACT) + "</td><td>1</td><td>1</td></tr>");
    }

    @Test
    void anUntestedNoteIsCountedByItsStudentsResultApartFromTheTestedFindings() {
        String html = YearAtAGlance.html(COHORT, List.of("0.00", "0.00", "1.00"));
        String row = "<tr><td>" + Html.escape(CellText.bounded(UNTESTED, CellText.MAX_CELL))
                + "</td><td>1</td><td>0</td></tr>";
        assertThat(html).as("the untested note's row, under the failed student who had it").contains(row);
        assertThat(html.indexOf(row)).as("the untested notes' table comes after the tested findings' table")
                .isGreaterThan(html.indexOf("Notes on what the course's scenes do not test"))
                .isGreaterThan(html.indexOf("<tr><td>" + Html.escape(FACT)));
    }

    @Test
    void aCataloguedMistakeIsCountedByItsEntry() {
        assertThat(YearAtAGlance.html(COHORT, List.of("0.00", "0.00", "1.00")))
                .as("the catalogue's row").contains("<tr><td>far root</td><td>1</td><td>0</td></tr>");
    }

    @Test
    void theSectionsToRereadAreCounted() {
        assertThat(YearAtAGlance.html(COHORT, List.of("0.00", "0.00", "1.00"))).as("a section's row")
                .contains("<tr><td>Handout section 5, Figure 6(b).</td><td>1</td><td>0</td></tr>");
    }

    @Test
    void theGradesAndTheTimesAreCounted() {
        String html = YearAtAGlance.html(COHORT, List.of("0.00", "0.00", "1.00"));
        assertThat(html).as("the grades").contains("<tr><td>1.00</td><td>1</td></tr>")
                .contains("<tr><td>0.00</td><td>2</td></tr>");
        assertThat(html).as("the times").contains("<tr><td>under 1 s</td><td>1</td></tr>")
                .contains("<tr><td>1 to 5 s</td><td>1</td></tr>").contains("<tr><td>60 s or more</td><td>1</td></tr>");
    }
}
