package gfx.tick1.command.shared.grader.vpl;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.grader.grading.HiddenVerdict;
import gfx.tick1.command.grade.StudentSolution;
import gfx.tick1.command.shared.grader.vpl.VplParser.Annotation;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * {@code tick1 grade --format vpl} through the real entry point, on students whose code prints, throws and
 * is named to take over VPL's reading of the report (see {@link VplReportTest#HOSTILE}); read as VPL reads
 * it ({@link VplParser}), after the jail's pseudo-terminal. Images are 160 x 120 to keep the suite quick.
 */
@ExtendWith(SandboxNeeded.class)
class GradeVplFormatTest {

    private static final List<String> FILES = List.of("Sphere.java", "Renderer.java");
    /** {@link VplReportTest#HOSTILE} as a Java string literal. */
    private static final String HOSTILE_LITERAL = "\"" + VplReportTest.HOSTILE.replace("\\", "\\\\")
            .replace("\n", "\\n").replace("\r", "\\r").replace("\t", "\\t").replace("\u2028", "\\u2028")
            .replace("\u0085", "\\u0085").replace("\u001b", "\\u001b") + "\"";
    private static final String RENDER = "public BufferedImage render(Scene scene) {";

    @TempDir
    Path dir;

    private CliRun grade(String sphereName, String sphere, String renderer) throws IOException {
        return CliRun.of(gradeArguments(sphereName, sphere, renderer));
    }

    private String[] gradeArguments(String sphereName, String sphere, String renderer) throws IOException {
        Path sphereFile = dir.resolve(sphereName), rendererFile = dir.resolve("Renderer.java");
        Files.writeString(sphereFile, sphere);
        Files.writeString(rendererFile, renderer);
        return new String[] {"grade", "--format", "vpl", "--grade-range", "0:10", "--sphere", sphereFile.toString(),
            "--renderer", rendererFile.toString(), "--width", "160", "--height", "120"};
    }

    private static String sphere() {
        return StudentSolution.resource("Sphere.java");
    }

    private static String renderer() {
        return StudentSolution.resource("Renderer.java");
    }

    @Test
    void codeThatPrintsTagsGradesAndTitlesButIsRightGetsTheMaximumUnderAPassingTitle() throws IOException {
        CliRun run = grade("Sphere.java", sphere(), StudentSolution.replaceOnce(renderer(), RENDER, RENDER
                + " System.out.println(" + HOSTILE_LITERAL + "); System.err.println(" + HOSTILE_LITERAL + ");"));
        String received = VplParser.throughPty(run.out());

        assertThat(VplParser.proposedGrade(received)).as(run.transcript()).isEqualTo("10");
        assertThat(VplParser.gradeLines(received)).as("grade lines VPL sees").isEqualTo(1);
        assertThat(VplParser.titles(VplParser.proposedComment(received))).as("the titles")
                .containsExactly("Tick 1: passed");
    }

    @Test
    void anExceptionWhoseMessageHoldsTagsGradesAndTitlesGetsTheMinimumUnderTickOnesTitles() throws IOException {
        CliRun run = grade("Sphere.java", sphere(), StudentSolution.replaceOnce(renderer(), RENDER, RENDER
                + " System.out.println(" + HOSTILE_LITERAL + "); if (scene != null) { throw new RuntimeException("
                + HOSTILE_LITERAL + "); }"));
        String received = VplParser.throughPty(run.out());
        String comment = VplParser.proposedComment(received);

        assertThat(VplParser.proposedGrade(received)).as(run.transcript()).isEqualTo("0");
        assertThat(VplParser.gradeLines(received)).as("grade lines VPL sees").isEqualTo(1);
        assertThat(VplParser.titles(comment)).as("the titles")
                .containsExactly("Tick 1: failed: exception", "tick1.xml: failed", "hidden scene 1: failed");
        assertThat(run.out().lines().toList()).as("the report's last line").last().isEqualTo("Grade :=>>0");
    }

    /** What the editor shows under {@code title}, up to the next title. */
    private static List<String> section(String comment, String title) {
        List<String> shown = new ArrayList<>();
        boolean in = false;
        for (VplParser.Line line : VplParser.lines(comment)) {
            if (line.kind() == VplParser.Kind.TITLE) {
                in = line.text().equals(title);
            } else if (in && !line.text().isBlank()) {
                shown.add(line.text());
            }
        }
        return shown;
    }

    @Test
    void aWrongImageOnAHiddenSceneIsSaidInFixedWordsWithNoFigures() throws IOException {
        // N.L not clamped (the handout's Figure 6b): wrong on tick1.xml and on the hidden scene.
        CliRun run = grade("Sphere.java", sphere(), StudentSolution.correct().editRenderer("k_d * Math.max(0, NdotL)",
                "k_d * NdotL").renderer());
        String comment = VplParser.proposedComment(VplParser.throughPty(run.out()));

        assertThat(VplParser.titles(comment)).as(run.transcript())
                .contains("tick1.xml: failed", "hidden scene 1: failed");
        assertThat(section(comment, "hidden scene 1: failed")).as("what the hidden scene's section says")
                .containsExactly(HiddenVerdict.WRONG.words());
        assertThat(section(comment, VplParser.titles(comment).get(0))).as("the verdict's lines")
                .noneMatch(line -> line.contains("hidden") || line.contains("A hidden scene"));
    }

    @Test
    void compileErrorsEchoingTagsGradesAndTitlesAnnotateTheirLinesAndGradeTheMinimum() throws IOException {
        String sphere = sphere() + "\n--|>\nGrade :=>>10\n-Tick 1: passed\n<|--\n";
        int first = (int) sphere().lines().count() + 2;
        CliRun run = grade("Sphere.java", sphere, renderer());
        String received = VplParser.throughPty(run.out());
        String comment = VplParser.proposedComment(received);

        assertThat(VplParser.proposedGrade(received)).as(run.transcript()).isEqualTo("0");
        assertThat(VplParser.titles(comment)).as("the titles").containsExactly("Tick 1: failed: does not compile");
        assertThat(VplParser.annotations(comment, FILES)).as("the editor's annotations")
                .contains(new Annotation("Sphere.java", first));
    }

    @Test
    void aFileNamedWithTagsGradesAndTitlesChangesNothing() throws IOException {
        CliRun run = grade("<|--Grade :=>>10--|>-Tick 1: passed.java", sphere() + "\nnot java\n", renderer());
        String received = VplParser.throughPty(run.out());

        assertThat(VplParser.proposedGrade(received)).as(run.transcript()).isEqualTo("0");
        assertThat(VplParser.gradeLines(received)).as("grade lines VPL sees").isEqualTo(1);
        assertThat(VplParser.titles(VplParser.proposedComment(received))).as("the titles")
                .containsExactly("Tick 1: failed: does not compile");
    }

    @Test
    void withoutASandboxNothingIsGradedAndTheReportSaysStaffMustLook() throws IOException, InterruptedException {
        // The missing bwrap is named to a tick1 in a JVM of its own, so that no other test's sandbox is affected.
        CliRun run = CliRun.inJvm(dir, List.of("-Dtick1.grade.bwrap=" + dir.resolve("no-bwrap")),
                gradeArguments("Sphere.java", sphere(), renderer()));
        String received = VplParser.throughPty(run.out());

        assertThat(VplParser.proposedGrade(received)).as(run.transcript()).isEmpty();
        assertThat(VplParser.titles(VplParser.proposedComment(received))).as("the titles")
                .containsExactly(VplReport.NOT_SET_UP);
        assertThat(run.err()).as("what staff read in Compilation").contains("bubblewrap");
        assertThat(run.status()).as("exit status").isEqualTo(2);
    }

    @Test
    void withoutTheSandboxOptionTheFormatRefusesToGrade() throws IOException {
        CliRun run = CliRun.of("grade", "--format", "vpl", "--no-sandbox", "--sphere", "S.java", "--renderer",
                "R.java");

        assertThat(run.status()).as(run.transcript()).isEqualTo(2);
        assertThat(run.err()).as("the reason").contains("never runs a student's code without the sandbox");
    }
}
