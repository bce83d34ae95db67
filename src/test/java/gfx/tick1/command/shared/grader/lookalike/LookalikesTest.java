package gfx.tick1.command.shared.grader.lookalike;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.diff.CorrectStyles;
import gfx.tick1.command.shared.grader.lookalike.Handwritten.Solution;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.javacode.Nesting;
import gfx.tick1.command.shared.kit.StarterKit;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * A cohort of independent solutions ({@link Handwritten}) with planted copies: the copies must be
 * listed, ranked above every honest pair, and the honest pairs not listed at all.
 */
class LookalikesTest {

    private static final List<Solution> HONEST = Handwritten.cohort();
    private static CodeReader reader;

    /** A copy of the second student's, its locals renamed and its independent declarations in another order. */
    static final Solution RENAMED_AND_REORDERED = HONEST.get(1)
            .sphere("double root1 = (-b + Math.sqrt(d)) / (2 * a);\n            "
                    + "double root2 = (-b - Math.sqrt(d)) / (2 * a);",
                    "double second = (-b - Math.sqrt(d)) / (2 * a);\n            "
                    + "double first = (-b + Math.sqrt(d)) / (2 * a);")
            .sphere("Math.min(root1, root2)", "Math.min(first, second)")
            .sphere("Math.max(root1, root2)", "Math.max(first, second)")
            .sphere("double d = ", "double disc = ").sphere("if (d >= 0) {", "if (disc >= 0) {")
            .renderer("Vector3 toLight = light.getPosition().subtract(P).normalised();\n        "
                    + "Vector3 toCamera = P.scale(-1).normalised();",
                    "Vector3 v = P.scale(-1).normalised();\n        "
                    + "Vector3 l = light.getPosition().subtract(P).normalised();")
            .renderer("toLight.reflectIn(N)", "l.reflectIn(N)").renderer("N.dot(toLight)", "N.dot(l)")
            .renderer("reflected.dot(toCamera)", "reflected.dot(v)").named("renamed and reordered copy");

    /** A copy of the first student's with comments added and the layout and parentheses changed. */
    static final Solution COMMENTS_AND_LAYOUT = HONEST.get(0)
            .sphere("if (near > 0) {", "// the nearer root first\n        if ((near > 0))\n        {")
            .sphere("double far = (-b + sqrtDisc) / (2 * a);",
                    "double far = ((-b) + (sqrtDisc)) / (2 * a); /* the other */")
            .renderer("colour = colour.add(C_diff", "colour = colour    // diffuse\n            .add(C_diff")
            .renderer("Vector3 R = L.reflectIn(N);", "Vector3 R =\n L.reflectIn(N);").named("comments and layout");

    /** The fifth student's, with a slip (R.V not clamped), as two students hand it in, one with a comment added. */
    static final Solution WRONG = HONEST.get(4).renderer("if (RdotV < 0) RdotV = 0;", "").named("wrong");
    static final Solution SAME_WRONG = WRONG.renderer("Vector3 R = L.reflectIn(N);",
            "Vector3 R = L.reflectIn(N); // mirror").named("the same wrong code");

    /** tick1's reference, its locals renamed. */
    static final Solution REFERENCE_COPY = referenceCopy();

    @BeforeAll
    static void prepare() {
        reader = new CodeReader(Lookalikes.MINIMUM_MATCH);
    }

    private static Solution referenceCopy() {
        CorrectStyles.Style renamed = CorrectStyles.layoutOnly().get(0);
        return new Solution("a copy of the reference", renamed.sphere(), renamed.renderer());
    }

    private static double similarity(Solution a, Solution b) {
        ComparedCode x = reader.read(a.sphere(), a.renderer());
        ComparedCode y = reader.read(b.sphere(), b.renderer());
        return Lookalikes.similarity(x, y, GreedyStringTiling.tiles(x.sequence, y.sequence));
    }

    private static double honestBest() {
        double best = 0;
        for (int i = 0; i < HONEST.size(); i++) {
            for (int j = i + 1; j < HONEST.size(); j++) {
                best = Math.max(best, similarity(HONEST.get(i), HONEST.get(j)));
            }
        }
        return best;
    }

    @Test
    void aRenamedAndReorderedCopyScoresAboveEveryHonestPair() {
        assertThat(similarity(RENAMED_AND_REORDERED, HONEST.get(1))).as("the renamed and reordered copy")
                .isGreaterThan(honestBest()).isGreaterThanOrEqualTo(Lookalikes.TOKEN_THRESHOLD);
    }

    @Test
    void aCopyWithCommentsAndLayoutChangedScoresAboveEveryHonestPair() {
        assertThat(similarity(COMMENTS_AND_LAYOUT, HONEST.get(0))).as("the copy with comments and layout changed")
                .isEqualTo(1.0);
    }

    @Test
    void theSameWrongCodeScoresAboveEveryHonestPair() {
        assertThat(similarity(WRONG, SAME_WRONG)).as("the same wrong code").isGreaterThan(honestBest())
                .isGreaterThanOrEqualTo(Lookalikes.TOKEN_THRESHOLD);
    }

    @Test
    void independentSolutionsInDifferentStylesScoreBelowTheThreshold() {
        assertThat(honestBest()).as("the most similar pair of independent solutions")
                .isLessThan(Lookalikes.TOKEN_THRESHOLD);
    }

    @Test
    void aCopyOfTheReferenceIsLikeTheReferenceAndIndependentSolutionsAreNot() {
        ComparedCode copy = reader.read(REFERENCE_COPY.sphere(), REFERENCE_COPY.renderer());
        assertThat(Lookalikes.similarity(copy, reader.reference(),
                GreedyStringTiling.tiles(copy.sequence, reader.reference().sequence)))
                .as("the reference with its locals renamed, against the reference").isEqualTo(1.0);
        for (Solution honest : HONEST) {
            ComparedCode code = reader.read(honest.sphere(), honest.renderer());
            assertThat(Lookalikes.similarity(code, reader.reference(),
                    GreedyStringTiling.tiles(code.sequence, reader.reference().sequence)))
                    .as("%s against the reference", honest).isLessThan(Lookalikes.TOKEN_THRESHOLD);
        }
    }

    @Test
    void theStarterAloneScoresZeroAgainstAnything() {
        Solution starter = new Solution("the starter", StarterKit.source("Sphere"), StarterKit.source("Renderer"));
        List<Solution> others = new ArrayList<>(HONEST);
        others.add(REFERENCE_COPY);
        others.add(starter);
        for (Solution other : others) {
            assertThat(similarity(starter, other)).as("the untouched starter against %s", other).isZero();
        }
        ComparedCode code = reader.read(starter.sphere(), starter.renderer());
        assertThat(code.counted()).as("tokens of the starter that are not the base").isZero();
    }

    @Test
    void theCohortListsThePlantedPairsFirstAndNoHonestPair() throws InterruptedException {
        // The fifth student's solution is in the cohort only as the two wrong copies made of it.
        List<Solution> cohort = new ArrayList<>(HONEST);
        cohort.remove(4);
        cohort.addAll(List.of(RENAMED_AND_REORDERED, COMMENTS_AND_LAYOUT, WRONG, SAME_WRONG, REFERENCE_COPY));
        List<StudentResult> results = new ArrayList<>();
        for (int i = 0; i < cohort.size(); i++) {
            results.add(result(i + 1, cohort.get(i), List.of()));
        }
        List<Lookalike> found = Lookalikes.find(results);
        Set<String> pairs = found.stream().map(LookalikesTest::describe).collect(Collectors.toSet());
        assertThat(pairs).as("the pairs listed").containsExactlyInAnyOrder(
                "min and max of the roots / renamed and reordered copy",
                "early returns / comments and layout",
                "wrong / the same wrong code",
                "a copy of the reference / " + Lookalikes.REFERENCE);
        assertThat(found).as("the pairs, most similar first").isSortedAccordingTo(
                (x, y) -> Double.compare(y.similarity(), x.similarity()));
    }

    @Test
    void failedSubmissionsWithTheSameRareWrongAnswersAreListedWhateverTheirTokens() throws InterruptedException {
        String figures = "mean difference R 1.000, G 2.000, B 3.000 levels; PSNR 40.00 dB";
        List<String> answer = List.of(figures,
                "verdict: unsure: no entry of the catalogue explains this image exactly");
        List<StudentResult> results = new ArrayList<>();
        for (int i = 0; i < HONEST.size(); i++) {
            StudentResult result = result(i + 1, HONEST.get(i), i < 2 ? answer : List.of());
            results.add(i < 2 ? result.withFindings(new Findings(null, List.of(), List.of(),
                    List.of("scene 1: " + figures), List.of())) : result);
        }
        List<Lookalike> found = Lookalikes.find(results);
        assertThat(found).as("the pairs listed").singleElement().satisfies(pair -> {
            assertThat(describe(pair)).as("the pair").isEqualTo("early returns / min and max of the roots");
            assertThat(pair.reason()).as("why").isEqualTo(Lookalike.Reason.SAME_UNCATALOGUED_ANSWERS);
            assertThat(pair.why()).as("the phrase").isEqualTo("the same uncatalogued wrong answer");
        });
    }

    /** A member nested deeper than any solution is not compared, and the note says so; the rest of the code is. */
    @Test
    void aMemberNestedBeyondTheBoundIsLeftOutWithANote() {
        Solution honest = HONEST.get(0);
        int depth = Nesting.MOST_DEPTH + 1;
        String sphere = honest.sphere().substring(0, honest.sphere().lastIndexOf('}'))
                + "    void deep() " + "{".repeat(depth) + "}".repeat(depth) + "\n}\n";

        ComparedCode code = reader.read(sphere, honest.renderer());

        assertThat(code.members()).as("the members compared").extracting(ComparedCode.Member::signature)
                .contains(CodeReader.INTERSECTION, CodeReader.ILLUMINATE).doesNotContain("deep()");
        assertThat(code.notes()).as("what was not compared").containsExactly("deep() in Sphere.java is not compared: "
                + "blocks, statements and expressions nested more than " + Nesting.MOST_DEPTH + " deep");
    }

    private static String describe(Lookalike pair) {
        return pair.a().fullName() + " / " + (pair.b() == null ? Lookalikes.REFERENCE : pair.b().fullName());
    }

    /** A result for {@code solution}, participant {@code id}: failed, with {@code explanation} on its one scene. */
    static StudentResult result(int id, Solution solution, List<String> explanation) {
        Submission submission = new Submission(solution.name() + "_" + id + "_assignsubmission_file_", "" + id,
                solution.name(), new Submission.SourceFile("Sphere.java",
                        solution.sphere().getBytes(StandardCharsets.UTF_8)),
                new Submission.SourceFile("Renderer.java", solution.renderer().getBytes(StandardCharsets.UTF_8)),
                null);
        boolean passed = explanation.isEmpty();
        return new StudentResult(submission, new StudentResult.Summary(passed, passed ? 1 : 0, 1,
                passed ? Category.Outcome.PASSED : Category.Outcome.UNRECOGNISED, ""),
                List.of(new SceneResult("tick1.xml", false, passed, explanation, SceneResult.Images.NONE)),
                Duration.ZERO);
    }

}
