package gfx.tick1.command.shared.grader.report;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.lookalike.Lookalike;
import gfx.tick1.command.shared.grader.lookalike.Lookalikes;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.kit.StarterKit;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** lookalikes.csv, the index's section and the side-by-side page, on two copies of hostile code. */
class LookalikeReportTest {

    /** A copy of the reference with a string literal and a comment that would be markup if written unescaped. */
    private static final String HOSTILE = "</pre><script>window.xssRan=1</script>";
    private static List<Lookalike> pairs;

    @BeforeAll
    static void findThePair() throws InterruptedException {
        String sphere = StarterKit.source("Sphere").replace("// TODO: Determine if ray and sphere intersect",
                "double discriminant = b * b - 4 * a * c;\n        if (discriminant < 0) {\n"
                + "            System.out.println(\"" + HOSTILE + "\");\n"
                + "            return new RaycastHit();\n        }\n"
                + "        double s = (-b - Math.sqrt(discriminant)) / (2 * a);\n"
                + "        if (s > 0) {\n            Vector3 point = ray.evaluateAt(s);\n"
                + "            return new RaycastHit(this, s, point, getNormalAt(point));\n        }");
        pairs = Lookalikes.find(List.of(student("=HYPERLINK(\"x\")", HOSTILE, sphere),
                student("2001", "Bob <b>", sphere + "// " + HOSTILE)));
    }

    private static StudentResult student(String id, String name, String sphere) {
        Submission submission = new Submission(name + "_" + id + "_assignsubmission_file_", id, name,
                new Submission.SourceFile("Sphere.java", sphere.getBytes(StandardCharsets.UTF_8)),
                new Submission.SourceFile("Renderer.java",
                        StarterKit.source("Renderer").getBytes(StandardCharsets.UTF_8)), null);
        return new StudentResult(submission, new StudentResult.Summary(false, 0, 1, Category.Outcome.UNRECOGNISED, ""),
                List.of(), Duration.ZERO);
    }

    @Test
    void theCsvNamesParticipantsAsTheWorksheetDoesAndKeepsCellsFromBeingFormulas() {
        assertThat(pairs).as("the pairs found").hasSize(1);
        assertThat(LookalikesCsv.csv(pairs)).as("lookalikes.csv").isEqualTo(
                "Identifier A,Identifier B,Similarity,Why\r\n"
                + "\"Participant =HYPERLINK(\"\"x\"\")\",Participant 2001,100%,same tokens after renaming (100%)\r\n");
    }

    @Test
    void theSideBySidePageEscapesTheStudentsCodeAndNames() {
        String page = LookalikePage.html(pairs.get(0));
        assertThat(page).as("the page").doesNotContain("<script>").doesNotContain("<b>")
                .contains("&lt;/script&gt;").contains("<mark>");
    }

    @Test
    void theIndexSectionLinksEachPairToItsPage() {
        String section = LookalikeSection.section(pairs, pairs.size());
        assertThat(section).as("the section").contains("href=\"lookalikes/pair-1.html\"").doesNotContain("<b>")
                .contains("lookalikes.csv");
    }
}
