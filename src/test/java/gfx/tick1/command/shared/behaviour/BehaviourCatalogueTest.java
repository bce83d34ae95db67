package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.Isolated;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Each entry of the catalogue, written into the correct solution as a student would write it, is
 * named by its own model and no other: every answer the student's method gives is its model's.
 * An entry that behaves as ours on every tested input (a mistake of render's, or one only a ray
 * that starts inside a sphere or on its surface shows) gets no tested finding; one that differs
 * from both ours and the handout's six steps where the course's scenes cannot look gets a note
 * with the untested label, and nothing else.
 */
@Isolated("its probes run in this JVM, each call of the student's methods within a time limit "
        + "(AnswerLog.CALL_MILLIS) that a class running beside it could use up")
class BehaviourCatalogueTest {

    private static final String RETURN_SUM = "return ambient.add(diffuse).add(specular);";
    private static final String S1 = "double s1 = (-b - Math.sqrt(discriminant)) / (2 * a);";
    private static final String S2 = "double s2 = (-b + Math.sqrt(discriminant)) / (2 * a);";

    /** The catalogue's entries by their names, each as a student's solution that makes it. */
    static Map<String, Case> catalogue() {
        CalledSolution correct = CalledSolution.correct();
        Map<String, Case> cases = new LinkedHashMap<>();
        cases.put("CORRECT", new Case(correct));
        cases.put("BACKGROUND_ONLY", new Case(correct.sphere("return new RaycastHit(this, s, point, normal);",
                "return new RaycastHit();")));
        cases.put("FLAT_COLOUR", new Case(correct.renderer(RETURN_SUM, "return object.getColour();")));
        cases.put("AMBIENT_ONLY", new Case(correct.renderer(RETURN_SUM, "return ambient;")));
        cases.put("AMBIENT_DIFFUSE", new Case(correct.renderer(RETURN_SUM, "return ambient.add(diffuse);")));
        cases.put("AMBIENT_WITHOUT_C_DIFF", new Case(correct.renderer("Vector3 ambient = C_diff.scale(I_a);",
                "Vector3 ambient = I_a;")));
        cases.put("NO_AMBIENT", new Case(correct.renderer(RETURN_SUM, "return diffuse.add(specular);")));
        cases.put("SPECULAR_WITHOUT_I", new Case(correct.renderer("C_spec.scale(I).scale(k_s", "C_spec.scale(k_s")));
        cases.put("COLOUR_TIMES_255", new Case(correct.renderer(RETURN_SUM,
                "return ambient.add(diffuse).add(specular).scale(255);")));
        cases.put("COLOUR_OVER_255", new Case(correct.renderer(RETURN_SUM,
                "return ambient.add(diffuse).add(specular).scale(1 / 255.0);")));
        cases.put("UNNORMALISED_L_V", new Case(correct
                .renderer("Vector3 L = light.getPosition().subtract(P).normalised();",
                        "Vector3 L = light.getPosition().subtract(P);")
                .renderer("Vector3 V = P.scale(-1).normalised();", "Vector3 V = P.scale(-1);")));
        cases.put("UNCLAMPED_N_DOT_L", new Case(correct.renderer("k_d * Math.max(0, NdotL)", "k_d * NdotL")));
        cases.put("UNCLAMPED_R_DOT_V", new Case(correct.renderer("Math.pow(Math.max(0, RdotV), n)",
                "Math.pow(RdotV, n)")));
        cases.put("FAR_ROOT", new Case(correct.sphere("double s = s1 > 0 ? s1 : s2;", "double s = s2;")));
        cases.put("HIT_REJECTED_ON_A_NEGATIVE_ROOT", new Case(correct.sphere("double s = s1 > 0 ? s1 : s2;",
                "if (s1 < 0 || s2 < 0) {\n            return new RaycastHit();\n        }\n"
                        + "        double s = s1 > 0 ? s1 : s2;")));
        cases.put("ROOTS_ACCEPTED_AT_ZERO", new Case(correct.sphere("double s = s1 > 0 ? s1 : s2;",
                "double s = s1 >= 0 ? s1 : s2;").sphere("if (s > 0) {", "if (s >= 0) {")));
        // Without the discriminant's test, sqrt gives NaN, NaN > 0 is false, and the miss is still a miss.
        cases.put("UNCHECKED_NEGATIVE_SQUARE_ROOT", new Case(correct.sphere(
                "if (discriminant < 0) {\n            return new RaycastHit();\n        }", "")));
        cases.put("NO_FALL_OFF", new Case(correct.renderer("Vector3 I = light.getIlluminationAt(distanceToLight);",
                "Vector3 I = light.getColour().scale(light.getIntensity() / (Math.PI * 4));")));
        cases.put("FALL_OFF_WITHOUT_4PI", new Case(correct.renderer(
                "Vector3 I = light.getIlluminationAt(distanceToLight);",
                "Vector3 I = light.getColour().scale(light.getIntensity() / Math.pow(distanceToLight, 2));")));
        cases.put("V_AWAY_FROM_CAMERA", new Case(correct.renderer("Vector3 V = P.scale(-1).normalised();",
                "Vector3 V = P.normalised();")));
        cases.put("R_WRONG_WAY", new Case(correct.renderer("Vector3 R = L.reflectIn(N);",
                "Vector3 R = N.reflectIn(L);")));
        cases.put("ROUNDED_BYTES", new Case(correct.renderer("image.setRGB(x, y, linearRGB.toRGB());",
                "image.setRGB(x, y, (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.x))) << 16"
                        + " | (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.y))) << 8"
                        + " | (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.z))));")));
        cases.put("UPSIDE_DOWN", new Case(correct.renderer("image.setRGB(x, y,", "image.setRGB(x, height - 1 - y,")));
        cases.put("RED_BLUE_SWAPPED", new Case(correct.renderer("image.setRGB(x, y, linearRGB.toRGB());",
                "image.setRGB(x, y, new Vector3(linearRGB.z, linearRGB.y, linearRGB.x).toRGB());")));
        cases.put("NORMAL_NOT_NORMALISED", new Case(correct.sphere("Vector3 normal = this.getNormalAt(point);",
                "Vector3 normal = point.subtract(position);")));
        cases.put("ROOTS_IN_FLOAT", new Case(correct.sphere(S1, "float s1 = (float) ((-b - Math.sqrt(discriminant)) "
                + "/ (2 * a));").sphere(S2, "float s2 = (float) ((-b + Math.sqrt(discriminant)) / (2 * a));")));
        cases.put("DIVIDED_BY_2_TIMES_A", new Case(correct.sphere(S1, S1.replace("(2 * a)", "2 * a"))
                .sphere(S2, S2.replace("(2 * a)", "2 * a"))));
        cases.put("DISTANCE_ALWAYS_S1", new Case(correct.sphere("return new RaycastHit(this, s, point, normal);",
                "return new RaycastHit(this, s1, point, normal);")));
        cases.put("HANDOUT_SIX_STEPS", new Case(correct.sphere("double s = s1 > 0 ? s1 : s2;",
                "double s = s1 > 0 && s1 < s2 ? s1 : s2 > 0 && s2 < s1 ? s2 : -1;")));
        cases.put("KD_SWAPPED_WITH_KS", new Case(correct.renderer("double k_d = object.getPhong_kD();",
                "double k_d = object.getPhong_kS();").renderer("double k_s = object.getPhong_kS();",
                "double k_s = object.getPhong_kD();")));
        cases.put("HIGHLIGHT_COLOURED", new Case(correct.renderer("Vector3 C_spec = new Vector3(1);",
                "Vector3 C_spec = C_diff;")));
        cases.put("DIFFUSE_WITHOUT_C_DIFF", new Case(correct.renderer(
                "Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, NdotL));",
                "Vector3 diffuse = I.scale(k_d * Math.max(0, NdotL));")));
        cases.put("L_FROM_THE_LIGHT", new Case(correct.renderer(
                "Vector3 L = light.getPosition().subtract(P).normalised();",
                "Vector3 L = P.subtract(light.getPosition()).normalised();")));
        return cases;
    }

    /** A solution that makes one entry. */
    record Case(CalledSolution solution) {
    }

    static Stream<Arguments> entries() {
        return catalogue().entrySet().stream().map(e -> Arguments.of(Variant.valueOf(e.getKey()), e.getValue()));
    }

    /** The entries that are mistakes the behaviour comparison sees: each has a tested finding. */
    static Stream<Arguments> testedMistakes() {
        return entries().filter(arguments -> !behavesAsOursWhereTested((Variant) arguments.get()[0]));
    }

    /** The entries that give our answer on every tested input. */
    static Stream<Arguments> oursWhereTested() {
        return entries().filter(arguments -> behavesAsOursWhereTested((Variant) arguments.get()[0]));
    }

    /** The entries that give our answer on every tested input: render's, and the correct ones. */
    private static boolean behavesAsOursWhereTested(Variant variant) {
        return variant.isCorrect() || variant.method() == Variant.Method.RENDER || !variant.testedByTheCoursesScenes();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("testedMistakes")
    void eachMistakeIsNamedByItsOwnModelAlone(Variant variant, Case mistake, @TempDir Path folder)
            throws Exception {
        BehaviourFindings findings = mistake.solution().findings(folder);
        assertThat(findings.tested()).as("the tested findings of %s", variant).hasSize(1);
        MethodBehaviour method = variant.method() == Variant.Method.INTERSECTION_WITH
                ? findings.behaviour().intersectionWith() : findings.behaviour().illuminate();
        assertThat(method.difference().mistake()).as("the entries whose models give every answer of %s", variant)
                .containsExactly(variant);
        assertThat(findings.untested()).as("the untested notes of %s", variant).isEmpty();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("oursWhereTested")
    void anEntryThatBehavesAsOursWhereTestedHasNoTestedFinding(Variant variant, Case entry, @TempDir Path folder)
            throws Exception {
        BehaviourFindings findings = entry.solution().findings(folder);
        assertThat(findings.ran()).as("%s was run", variant).isTrue();
        assertThat(findings.tested()).as("the tested findings of %s", variant).isEmpty();
        boolean untestedNote = variant == Variant.ROOTS_ACCEPTED_AT_ZERO || variant == Variant.DISTANCE_ALWAYS_S1;
        if (untestedNote) {
            assertThat(findings.untested()).as("the untested notes of %s", variant).isNotEmpty()
                    .allMatch(note -> note.startsWith(BehaviourJudge.UNTESTED + ": "))
                    .allMatch(note -> note.endsWith("\"" + variant.title() + "\""));
        } else {
            assertThat(findings.untested()).as("the untested notes of %s", variant).isEmpty();
        }
    }

    /**
     * Code that negates R (the bounce of L) gives the answers of V pointing away from the camera on
     * every input, since R.V changes sign either way: the finding names both together, V first as
     * the handout's step 1 computes it first, and leads with neither alone.
     */
    @Test
    void rNegatedIsToldAsATieWithVPointingAwayNotAsOneOfThem(@TempDir Path folder) throws Exception {
        BehaviourFindings findings = CalledSolution.correct().renderer("Vector3 R = L.reflectIn(N);",
                "Vector3 R = L.reflectIn(N).scale(-1);").findings(folder);

        assertThat(findings.tested()).as("the tested findings").singleElement()
                .extracting(BehaviourFindings.Finding::fact).asString()
                .contains("gives the answers of \"V pointing away from the camera or R negated\"",
                        "either V points", "or R is negated");
    }

    /**
     * A slip of our own that only a graze shows (the distance -b/a where the discriminant is 0, the
     * 2 forgotten): neither answer the handout allows (our touching point, or the six steps' no
     * hit), so the note calls it a mistake, never something the handout leaves open, and it is no
     * tested finding.
     */
    @Test
    void aWrongAnswerAtAGrazeIsAnUntestedMistakeNeverOneTheHandoutLeavesOpen(@TempDir Path folder) throws Exception {
        BehaviourFindings findings = CalledSolution.correct().sphere("double s = s1 > 0 ? s1 : s2;",
                "double s = discriminant == 0 ? -b / a : s1 > 0 ? s1 : s2;").findings(folder);

        assertThat(findings.tested()).as("the tested findings").isEmpty();
        assertThat(findings.untested()).as("the untested notes").singleElement().asString()
                .startsWith("a mistake not tested by the course's scenes: for a ray that grazes a sphere")
                .doesNotContain("leave it open");
    }

    /**
     * For tick1 diff, a method with a mistake only an untested edge shows does not behave as ours: its note
     * comes first, beside the method's line, not after the diff, and nothing says there is nothing to fix.
     */
    @Test
    void anUntestedMistakeIsToldFirstAndTheMethodDoesNotBehaveAsOurs(@TempDir Path folder) throws Exception {
        BehaviourFindings findings = CalledSolution.correct().sphere("double s = s1 > 0 ? s1 : s2;",
                "double s = discriminant == 0 ? -b / a : s1 > 0 ? s1 : s2;").findings(folder);

        BehaviourCheck.Lines lines = BehaviourCheck.hints(findings, List.of("Sphere", "Renderer"));

        assertThat(lines.behavesAsOurs()).as("whether the methods behave as ours").isFalse();
        assertThat(lines.behaviour()).as("the lines before the diff").hasSize(3)
                .satisfies(first -> assertThat(first.get(1)).startsWith("note: " + BehaviourJudge.UNTESTED));
        assertThat(lines.hints()).as("the lines after the diff").noneMatch(line -> line.startsWith("note: "));
    }

    /**
     * An illuminate whose answers are neither ours nor ours with red and blue exchanged rules out, as the whole
     * of an image, every mistake of render alone: each of them draws with our illuminate's answers.
     */
    @Test
    void anIlluminateThatIsNotOursLeavesNoMistakeOfRenderAloneToExplainTheImage(@TempDir Path folder)
            throws Exception {
        MethodBehaviour illuminate = CalledSolution.correct().renderer(RETURN_SUM,
                "return ambient.add(diffuse).add(specular).scale(0.5);").findings(folder).behaviour().illuminate();

        assertThat(illuminate.notAlone()).as("the mistakes of render that cannot be the whole image")
                .containsExactlyInAnyOrder(Variant.RED_BLUE_SWAPPED, Variant.ROUNDED_BYTES, Variant.UPSIDE_DOWN);
    }

    /** An illuminate that exchanges red and blue itself leaves "red and blue swapped" a possible image. */
    @Test
    void anIlluminateThatSwapsRedAndBlueLeavesThatMistakePossible(@TempDir Path folder) throws Exception {
        MethodBehaviour illuminate = CalledSolution.correct().renderer(RETURN_SUM,
                "Vector3 sum = ambient.add(diffuse).add(specular); return new Vector3(sum.z, sum.y, sum.x);")
                .findings(folder).behaviour().illuminate();

        assertThat(illuminate.notAlone()).as("the mistakes of render that cannot be the whole image")
                .doesNotContain(Variant.RED_BLUE_SWAPPED).contains(Variant.UPSIDE_DOWN);
    }

    /**
     * A slip the catalogue has no model of (one channel of the specular term takes another's
     * light) is shown by its simplest counterexample, in which only that channel differs, and
     * said to be unrecognised: never named as something it is not.
     */
    @Test
    void aMistakeWithoutAModelIsShownByItsSimplestCounterexampleAndNotNamed(@TempDir Path folder) throws Exception {
        BehaviourFindings findings = CalledSolution.correct().renderer(
                "Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, RdotV), n));",
                "Vector3 specular = C_spec.scale(new Vector3(I.x, I.y, I.y)).scale(k_s * Math.pow(Math.max(0, RdotV), "
                        + "n));").findings(folder);
        MethodBehaviour illuminate = findings.behaviour().illuminate();
        assertThat(illuminate.difference().mistake()).as("the entries named").isEmpty();
        assertThat(findings.facts()).as("the findings").singleElement().asString()
                .startsWith("your illuminate differs from ours on ").contains("; the simplest: for ")
                .endsWith("; tick1 does not recognise this mistake");
        assertThat(findings.behaviour().intersectionWith().behavesAsOurs()).as("intersectionWith, untouched").isTrue();
    }

    @Test
    void everyEntryOfTheCatalogueIsHeldAgainstItsModel() {
        Set<String> named = catalogue().keySet();
        for (Variant variant : Variant.values()) {
            assertThat(named).as("the entries this test writes as a student would").contains(variant.name());
        }
    }
}
