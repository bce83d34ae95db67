package gfx.tick1.command.shared.grader.vpl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gfx.tick1.command.shared.grader.grading.HiddenVerdict;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.LongFindings;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.vpl.VplParser.Annotation;
import gfx.tick1.command.shared.grader.vpl.VplParser.Kind;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@code tick1 grade --format vpl}'s report, read as VPL reads it ({@link VplParser}: moodle-mod_vpl's
 * vpl_submission.class.php and amd/src/vplutil.js), after the jail's pseudo-terminal has made each line
 * end {@code \r\n}: the grade it proposes, the titles its editor shows, and what no student text can do.
 */
class VplReportTest {

    /** Everything a student might print or throw to take over VPL's reading of the report. */
    static final String HOSTILE = "--|>\n<|--\nGrade :=>>10\n-Tick 1: passed\r-Tick 1: passed (10)\rGrade :=>>10\n"
            + "  --|>\t\n\tGrade :=>>10\nComment :=>>forged\u2028-Tick 1: passed\u0085\u001b[2J";

    private static final GradeRange TEN = GradeRange.parse("0:10");
    private static final List<String> FILES = List.of("Sphere.java", "Renderer.java");

    private static StudentResult result(boolean passed, String diagnosis, String reason, SceneResult... scenes) {
        return new StudentResult(new Submission("", "", "", null, null, null), new StudentResult.Summary(passed,
                passed ? scenes.length : 0, scenes.length, new Category.Mistake(diagnosis), reason), List.of(scenes),
                Duration.ZERO);
    }

    private static SceneResult failed(String name, boolean hidden, String... explanation) {
        return new SceneResult(name, hidden, false, List.of(explanation), SceneResult.Images.NONE);
    }

    /** The report as VPL receives it from vpl_execution. */
    private static String received(String report) {
        return VplParser.throughPty(report);
    }

    @Test
    void aPassProposesTheMaximumGradeUnderAPassingTitle() {
        String report = received(VplReport.of(result(true, "passed", "Congratulations! Your code passed the tester.",
                new SceneResult("tick1.xml", false, true, List.of(), SceneResult.Images.NONE)), List.of(), TEN));

        assertThat(VplParser.proposedGrade(report)).as("the grade VPL proposes").isEqualTo("10");
        assertThat(VplParser.titles(VplParser.proposedComment(report))).as("the titles the editor shows")
                .containsExactly("Tick 1: passed");
        assertThat(VplParser.proposedComment(report)).as("the comment").contains("Congratulations!");
    }

    @Test
    void aHiddenSceneOnWhichTheCodeThrewIsSaidInFixedWordsAndNotItsException() {
        String report = received(VplReport.of(result(false, "exception", "FAILED: 1 of 2 scenes wrong. hidden scene "
                + "1: the code threw java.lang.IllegalStateException (its message is not shown for a hidden scene).",
                new SceneResult("tick1.xml", false, true, List.of(), SceneResult.Images.NONE),
                failed("secret.xml", true, HiddenVerdict.THREW.words())), List.of(), TEN));
        String comment = VplParser.proposedComment(report);

        assertThat(VplParser.titles(comment)).as("the titles")
                .containsExactly("Tick 1: failed", "hidden scene 1: failed");
        assertThat(VplParser.lines(comment)).as("the comment's lines").map(VplParser.Line::text)
                .noneMatch(line -> line.contains("IllegalStateException"))
                .contains("FAILED: 1 of 2 scenes wrong.", HiddenVerdict.THREW.words());
    }

    @Test
    void aFailProposesTheMinimumGradeWithItsDiagnosisAsTitleAndItsReasonsBelow() {
        String report = received(VplReport.of(result(false, "N.L not clamped (Figure 6b)",
                "FAILED: 1 of 2 scenes wrong. tick1.xml is exactly the image of \"N.L not clamped (Figure 6b)\".",
                failed("tick1.xml", false, "12000 pixels differ", "reread: section 2.4")), List.of(), TEN));

        assertThat(VplParser.proposedGrade(report)).as("the grade VPL proposes").isEqualTo("0");
        assertThat(VplParser.titles(VplParser.proposedComment(report))).as("the titles the editor shows")
                .containsExactly("Tick 1: failed: N.L not clamped (Figure 6b)", "tick1.xml: failed");
        assertThat(VplParser.lines(VplParser.proposedComment(report))).as("the lines below the titles")
                .contains(new VplParser.Line(Kind.PREFORMATTED, "reread: section 2.4"));
    }

    @Test
    void anExceptionMessageOfTagsGradesAndTitlesNeitherGradesNorTitlesNorEndsTheComment() {
        String report = received(VplReport.of(result(false, "exception", "FAILED: 1 of 1 scene wrong. tick1.xml: the "
                + "code threw java.lang.RuntimeException: " + HOSTILE, failed("tick1.xml", false,
                ("the code threw java.lang.RuntimeException: " + HOSTILE).split("\n"))), List.of(), TEN));
        String comment = VplParser.proposedComment(report);

        assertThat(VplParser.proposedGrade(report)).as("the grade VPL proposes").isEqualTo("0");
        assertThat(VplParser.gradeLines(report)).as("grade lines VPL sees").isEqualTo(1);
        assertThat(VplParser.titles(comment)).as("the titles the editor shows")
                .containsExactly("Tick 1: failed: exception", "tick1.xml: failed");
        assertThat(comment).as("the comment holds all the report, to its last section")
                .contains("the code threw java.lang.RuntimeException:")
                .endsWith(">Comment :=> >forged-Tick 1: passed[2J\n");
        assertThat(VplParser.lines(comment)).as("every line below a title is preformatted (the last, after the "
                + "block's last line break, is empty)")
                .allMatch(line -> line.kind() != Kind.TEXT || line.text().isEmpty());
    }

    @Test
    void theGradeIsTheReportsLastLine() {
        String report = VplReport.of(result(false, "exception", HOSTILE, failed("tick1.xml", false, HOSTILE)),
                List.of(), TEN);

        assertThat(report.lines().toList()).as("the report's lines").last().isEqualTo("Grade :=>>0");
        assertThat(report.lines().filter(line -> line.startsWith("--|>")).count()).as("block ends").isEqualTo(1);
    }

    @Test
    void aCompileErrorAnnotatesItsLineInTheEditorAndItsEchoedSourceIsQuoted() {
        String error = "Sphere.java:35:36: error: ';' expected\n        String s = \"" + HOSTILE.replace("\n", " ")
                + "\"\n                                   ^";
        String report = received(VplReport.of(result(false, "does not compile",
                "FAILED: the code does not compile (1 error): Sphere.java:35:36: error: ';' expected"),
                List.of(error), TEN));
        String comment = VplParser.proposedComment(report);

        assertThat(VplParser.annotations(comment, FILES)).as("the editor's annotations")
                .containsExactly(new Annotation("Sphere.java", 35));
        assertThat(VplParser.titles(comment)).as("the titles").containsExactly("Tick 1: failed: does not compile");
        assertThat(VplParser.proposedGrade(report)).as("the grade").isEqualTo("0");
    }

    @Test
    void aCompileErrorEchoingLinesOfTagsAndGradesKeepsThemInsideTheComment() {
        // javac quotes one source line; a student's multi-line text block can put any of these in one.
        List<String> errors = List.of("Renderer.java:3:1: error: class, interface, enum, or record expected\n--|>",
                "Renderer.java:4:1: error: illegal start of type\nGrade :=>>10",
                "Renderer.java:5:1: error: illegal start of type\n-Tick 1: passed\r<|--");
        String report = received(VplReport.of(result(false, "does not compile",
                "FAILED: the code does not compile (3 errors): Renderer.java:3:1: error: ..."), errors, TEN));
        String comment = VplParser.proposedComment(report);

        assertThat(VplParser.proposedGrade(report)).as("the grade").isEqualTo("0");
        assertThat(VplParser.titles(comment)).as("the titles").containsExactly("Tick 1: failed: does not compile");
        assertThat(VplParser.annotations(comment, FILES)).as("the editor's annotations").extracting(Annotation::line)
                .containsExactly(3, 4, 5);
    }

    @Test
    void aFileNameOfTagsAndGradesIsQuotedWithItsTagsBroken() {
        String name = "<|--\n--|>Grade :=>>10\r-Tick 1: passed.java";
        String report = received(VplReport.of(result(false, "not UTF-8", "FAILED: " + name + ": not UTF-8"),
                List.of(), TEN));

        assertThat(VplParser.proposedGrade(report)).as("the grade").isEqualTo("0");
        assertThat(VplParser.gradeLines(report)).as("grade lines").isEqualTo(1);
        assertThat(VplParser.titles(VplParser.proposedComment(report))).as("the titles")
                .containsExactly("Tick 1: failed: not UTF-8");
        assertThat(report).as("the report").doesNotContain("<|--\r\n--|>", "--|>Grade").contains("- -|>Grade :=> >10");
    }

    @Test
    void aTitleEndingInANumberInBracketsKeepsItWithAFullStop() {
        String comment = VplParser.proposedComment(VplReport.of(result(false, "a mistake (2)", "FAILED."), List.of(),
                TEN));

        assertThat(VplParser.titles(comment)).as("the title the editor shows")
                .containsExactly("Tick 1: failed: a mistake (2).");
    }

    @Test
    void theGradeIsAPlainDecimalOfTheRange() {
        GradeRange range = GradeRange.parse("0.0:7.50");

        assertThat(range.grade(true)).as("a pass").isEqualTo("7.5");
        assertThat(range.grade(false)).as("a fail").isEqualTo("0");
        assertThat(GradeRange.parse("1:100").grade(true)).as("a pass of 100, not 1E+2").isEqualTo("100");
    }

    @Test
    void aRangeWithADecimalCommaOrUpsideDownIsRefused() {
        assertThatThrownBy(() -> GradeRange.parse("0:7,5")).as("a comma, which VPL reads as 7")
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("7,5");
        assertThatThrownBy(() -> GradeRange.parse("10:0")).as("the minimum above the maximum")
                .isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void whereTheTesterIsNotSetUpOneCommentSaysSoAndNoGradeIsProposed() {
        String report = received(VplReport.notSetUp());

        assertThat(VplParser.proposedGrade(report)).as("the grade VPL proposes").isEmpty();
        assertThat(VplParser.titles(VplParser.proposedComment(report))).as("the titles")
                .containsExactly(VplReport.NOT_SET_UP);
    }

    @Test
    void textIsCleanedOfControlCharactersAndLoneCarriageReturns() {
        assertThat(VplText.clean("a\rb\r\nc\u0007d\u202Ee\tf")).as("cleaned").isEqualTo("ab\ncde f");
    }

    /** The text of a comment's quoted lines, joined as they were before the report wrapped them. */
    private static String unwrapped(String comment) {
        return String.join("", VplParser.lines(comment).stream().filter(line -> line.kind() == Kind.PREFORMATTED)
                .map(VplParser.Line::text).toList());
    }

    @Test
    void everyFindingAndTheRereadLineOfALongExplanationReachTheStudent() {
        String comment = VplParser.proposedComment(received(VplReport.of(result(false, "differs from ours",
                LongFindings.REASON, failed("tick1.xml", false, "98343 pixels differ", "behaviour: "
                        + LongFindings.INTERSECTION, "behaviour: " + LongFindings.ILLUMINATE, LongFindings.REREAD)),
                List.of(), TEN)));

        assertThat(unwrapped(comment)).as("the comment, unwrapped")
                .contains("behaviour: " + LongFindings.INTERSECTION, "behaviour: " + LongFindings.ILLUMINATE,
                        LongFindings.REREAD).doesNotContain("not shown");
    }

    @Test
    void aLongReasonIsCutAfterAWholeFindingAndSaysTheRestIsBelow() {
        String comment = VplParser.proposedComment(received(VplReport.of(result(false, "differs from ours",
                LongFindings.REASON, failed("tick1.xml", false, "98343 pixels differ")), List.of(), TEN)));

        assertThat(unwrapped(comment.substring(0, comment.indexOf("-tick1.xml: failed")))).as("the reason's section")
                .isEqualTo(LongFindings.HEAD + " " + LongFindings.sentence(LongFindings.INTERSECTION)
                        + " (more below)");
    }

    @Test
    void everyNoteOfAPassReachesTheStudent() {
        String note = "a mistake not tested by the course's scenes: " + LongFindings.INTERSECTION;
        String other = "your illuminate differs from ours on 2 of 1010 inputs; " + LongFindings.ILLUMINATE;
        String comment = VplParser.proposedComment(received(VplReport.of(result(true, "passed",
                "Congratulations! Your code passed the tester. Note: " + note + "; " + other + ".",
                new SceneResult("tick1.xml", false, true, List.of("note: " + note, "note: " + other),
                        SceneResult.Images.NONE)), List.of(), TEN)));

        assertThat(unwrapped(comment)).as("the comment, unwrapped").contains(note, other)
                .doesNotContain("not shown");
        assertThat(VplParser.titles(comment)).as("the titles").first().isEqualTo("Tick 1: passed");
    }
}
