package gfx.tick1.grade.grading;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Each mistake of the diagnose catalogue, written into the correct solution as a student would
 * write it, fails exactly the probes of its own property; the correct solution fails none. A
 * mistake that only {@code render} makes (rounding, rows upside down, red and blue swapped when
 * packing) fails none either: the probes call intersectionWith and illuminate only.
 */
class ProbeCatalogueTest {

    private static final String RETURN_SUM = "return ambient.add(diffuse).add(specular);";

    /** The catalogue's mistakes by the names of gfx.tick1.diagnose.Variant, with the probes each must fail. */
    static Map<String, Case> catalogue() {
        ProbedSolution correct = ProbedSolution.correct();
        Map<String, Case> cases = new LinkedHashMap<>();
        cases.put("CORRECT", new Case(correct));
        cases.put("BACKGROUND_ONLY", new Case(correct.sphere("return new RaycastHit(this, s, point, normal);",
                "return new RaycastHit();"), Probe.HIT));
        cases.put("FLAT_COLOUR", new Case(correct.renderer(RETURN_SUM, "return object.getColour();"),
                Probe.PLACEHOLDER));
        cases.put("AMBIENT_ONLY", new Case(correct.renderer(RETURN_SUM, "return ambient;"), Probe.DIFFUSE,
                Probe.SPECULAR));
        cases.put("AMBIENT_DIFFUSE", new Case(correct.renderer(RETURN_SUM, "return ambient.add(diffuse);"),
                Probe.SPECULAR));
        cases.put("AMBIENT_WITHOUT_C_DIFF", new Case(correct.renderer("Vector3 ambient = C_diff.scale(I_a);",
                "Vector3 ambient = I_a;"), Probe.CHANNELS));
        cases.put("NO_AMBIENT", new Case(correct.renderer(RETURN_SUM, "return diffuse.add(specular);"),
                Probe.AMBIENT));
        cases.put("SPECULAR_WITHOUT_I", new Case(correct.renderer("C_spec.scale(I).scale(k_s", "C_spec.scale(k_s"),
                Probe.SPECULAR_WITH_I));
        cases.put("COLOUR_TIMES_255", new Case(correct.renderer(RETURN_SUM,
                "return ambient.add(diffuse).add(specular).scale(255);"), Probe.SCALE));
        cases.put("COLOUR_OVER_255", new Case(correct.renderer(RETURN_SUM,
                "return ambient.add(diffuse).add(specular).scale(1 / 255.0);"), Probe.SCALE));
        cases.put("UNNORMALISED_L_V", new Case(correct
                .renderer("Vector3 L = light.getPosition().subtract(P).normalised();",
                        "Vector3 L = light.getPosition().subtract(P);")
                .renderer("Vector3 V = P.scale(-1).normalised();", "Vector3 V = P.scale(-1);"),
                Probe.FALL_OFF, Probe.V_UNIT));
        cases.put("UNCLAMPED_N_DOT_L", new Case(correct.renderer("k_d * Math.max(0, NdotL)", "k_d * NdotL"),
                Probe.N_DOT_L_CLAMPED));
        cases.put("UNCLAMPED_R_DOT_V", new Case(correct.renderer("Math.pow(Math.max(0, RdotV), n)",
                "Math.pow(RdotV, n)"), Probe.R_DOT_V_CLAMPED));
        cases.put("FAR_ROOT", new Case(correct.sphere("double s = s1 > 0 ? s1 : s2;", "double s = s2;"),
                Probe.NEAREST_ROOT));
        cases.put("HIT_REJECTED_ON_A_NEGATIVE_ROOT", new Case(correct.sphere("double s = s1 > 0 ? s1 : s2;",
                "if (s1 < 0 || s2 < 0) {\n            return new RaycastHit();\n        }\n"
                        + "        double s = s1 > 0 ? s1 : s2;"), Probe.INSIDE));
        cases.put("ROOTS_ACCEPTED_AT_ZERO", new Case(correct.sphere("double s = s1 > 0 ? s1 : s2;",
                "double s = s1 >= 0 ? s1 : s2;").sphere("if (s > 0) {", "if (s >= 0) {"), Probe.ON_SURFACE));
        // Without the discriminant's test, sqrt gives NaN, NaN > 0 is false, and the miss is still a miss:
        // the method behaves as the reference's, so no probe may say otherwise.
        cases.put("UNCHECKED_NEGATIVE_SQUARE_ROOT", new Case(correct.sphere(
                "if (discriminant < 0) {\n            return new RaycastHit();\n        }", "")));
        cases.put("NO_FALL_OFF", new Case(correct.renderer("Vector3 I = light.getIlluminationAt(distanceToLight);",
                "Vector3 I = light.getColour().scale(light.getIntensity() / (Math.PI * 4));"), Probe.FALL_OFF));
        cases.put("FALL_OFF_WITHOUT_4PI", new Case(correct.renderer(
                "Vector3 I = light.getIlluminationAt(distanceToLight);",
                "Vector3 I = light.getColour().scale(light.getIntensity() / Math.pow(distanceToLight, 2));"),
                Probe.DIFFUSE));
        cases.put("V_AWAY_FROM_CAMERA", new Case(correct.renderer("Vector3 V = P.scale(-1).normalised();",
                "Vector3 V = P.normalised();"), Probe.CAMERA_DIRECTION));
        cases.put("R_WRONG_WAY", new Case(correct.renderer("Vector3 R = L.reflectIn(N);",
                "Vector3 R = N.reflectIn(L);"), Probe.REFLECTION));
        cases.put("ROUNDED_BYTES", new Case(correct.renderer("image.setRGB(x, y, linearRGB.toRGB());",
                "image.setRGB(x, y, (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.x))) << 16"
                        + " | (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.y))) << 8"
                        + " | (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.z))));")));
        cases.put("UPSIDE_DOWN", new Case(correct.renderer("image.setRGB(x, y,", "image.setRGB(x, height - 1 - y,")));
        cases.put("RED_BLUE_SWAPPED", new Case(correct.renderer("image.setRGB(x, y, linearRGB.toRGB());",
                "image.setRGB(x, y, new Vector3(linearRGB.z, linearRGB.y, linearRGB.x).toRGB());")));
        return cases;
    }

    /** A solution and the probes it must fail. */
    record Case(ProbedSolution solution, Set<Probe> fails) {
        Case(ProbedSolution solution, Probe... fails) {
            this(solution, fails.length == 0 ? EnumSet.noneOf(Probe.class) : EnumSet.of(fails[0], fails));
        }
    }

    static Stream<Arguments> mistakes() {
        return catalogue().entrySet().stream().map(e -> Arguments.of(e.getKey(), e.getValue()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("mistakes")
    void eachEntryOfTheCatalogueFailsExactlyItsOwnProbes(String variant, Case mistake, @TempDir Path folder)
            throws Exception {
        List<Probe> failed = mistake.solution().failedProbes(folder);
        assertThat(failed).as("the probes %s fails", variant).containsExactlyInAnyOrderElementsOf(mistake.fails());
    }

    @Test
    void everyEntryOfTheCatalogueIsHeldAgainstTheProbes() {
        Set<String> named = catalogue().keySet();
        for (gfx.tick1.diagnose.Variant variant : gfx.tick1.diagnose.Variant.values()) {
            assertThat(named).as("the probe test's mistakes").contains(variant.name());
        }
        for (String name : named) {
            assertThat(gfx.tick1.diagnose.Variant.valueOf(name)).as("an entry of the catalogue").isNotNull();
        }
    }

    @Test
    void everyProbeIsTheOwnPropertyOfSomeMistakeOrIsLeftOpenByTheHandout() {
        Set<Probe> owned = EnumSet.noneOf(Probe.class);
        catalogue().values().forEach(c -> owned.addAll(c.fails()));
        for (Probe probe : Probe.values()) {
            if (!owned.contains(probe)) {
                // The probes no catalogue mistake fails are the edge cases the handout leaves open, and the
                // generic shapes of a hit (its point, its normal, a hit where there is none).
                assertThat(EnumSet.of(Probe.MISS, Probe.POINTS_AWAY, Probe.BEHIND, Probe.POINT, Probe.NORMAL,
                        Probe.GRAZE)).as("probe %s, which no mistake of the catalogue fails", probe).contains(probe);
            }
        }
    }
}
