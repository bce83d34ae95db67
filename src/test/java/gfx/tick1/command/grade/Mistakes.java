package gfx.tick1.command.grade;

import gfx.tick1.command.shared.behaviour.Variant;
import java.util.EnumSet;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.params.provider.Arguments;

/**
 * Each mistake of the diagnose catalogue, made as a student would make it in Sphere.java or
 * Renderer.java: the submissions that GradeCohortTest's cohort holds one of each, and that the
 * grade tests of one student take their slips from.
 */
final class Mistakes {

    static final String DIFFUSE = "k_d * Math.max(0, NdotL)";
    static final String NEAR_ROOT = "double s = s1 > 0 ? s1 : s2;";
    private static final String RGB = "image.setRGB(x, y, linearRGB.toRGB());";
    private static final String SUM = "return ambient.add(diffuse).add(specular);";

    /** A mistake that shows only where the camera is inside a sphere, which neither default scene has. */
    static final StudentSolution HIT_REJECTED_ON_A_NEGATIVE_ROOT = StudentSolution.correct().editSphere(NEAR_ROOT,
            "if (s1 < 0 || s2 < 0) {\n            return new RaycastHit();\n        }\n        " + NEAR_ROOT);

    /** A mistake that shows only where a sphere's surface passes exactly through the camera. */
    static final StudentSolution ROOTS_ACCEPTED_AT_ZERO = StudentSolution.correct()
            .editSphere(NEAR_ROOT, "double s = s1 >= 0 ? s1 : s2;").editSphere("if (s > 0) {", "if (s >= 0) {");

    /** The mistakes made in render alone, which no probe of intersectionWith and illuminate sees. */
    static final Set<Variant> RENDER_ONLY = EnumSet.of(Variant.ROUNDED_BYTES, Variant.UPSIDE_DOWN,
            Variant.RED_BLUE_SWAPPED);

    private Mistakes() {
    }

    /** The mistakes that tick1.xml and the hidden scene show: each entry and a student's solution that makes it. */
    static Stream<Arguments> onTheCoursesScenes() {
        StudentSolution correct = StudentSolution.correct();
        return Stream.of(
                Arguments.of(Variant.BACKGROUND_ONLY, StudentSolution.untouchedStarterKit()),
                Arguments.of(Variant.FLAT_COLOUR, correct.withStarterRenderer()),
                Arguments.of(Variant.AMBIENT_ONLY, correct.editRenderer(SUM, "return ambient;")),
                Arguments.of(Variant.AMBIENT_DIFFUSE, correct.editRenderer(SUM, "return ambient.add(diffuse);")),
                Arguments.of(Variant.AMBIENT_WITHOUT_C_DIFF, correct.editRenderer(
                        "Vector3 ambient = C_diff.scale(I_a);", "Vector3 ambient = I_a;")),
                Arguments.of(Variant.NO_AMBIENT, correct.editRenderer(SUM, "return diffuse.add(specular);")),
                Arguments.of(Variant.COLOUR_TIMES_255, correct.editRenderer(SUM, SUM.replace(";", ".scale(255);"))),
                Arguments.of(Variant.COLOUR_OVER_255,
                        correct.editRenderer(SUM, SUM.replace(";", ".scale(1.0 / 255);"))),
                Arguments.of(Variant.SPECULAR_WITHOUT_I,
                        correct.editRenderer("C_spec.scale(I).scale(k_s", "C_spec.scale(k_s")),
                Arguments.of(Variant.UNNORMALISED_L_V, correct
                        .editRenderer("subtract(P).normalised();", "subtract(P);")
                        .editRenderer("Vector3 V = P.scale(-1).normalised();", "Vector3 V = P.scale(-1);")),
                Arguments.of(Variant.UNCLAMPED_N_DOT_L, correct.editRenderer(DIFFUSE, "k_d * NdotL")),
                Arguments.of(Variant.UNCLAMPED_R_DOT_V, correct.editRenderer(
                        "Math.pow(Math.max(0, RdotV), n)", "Math.pow(RdotV, n)")),
                Arguments.of(Variant.FAR_ROOT, correct.editSphere(NEAR_ROOT, "double s = s2;")),
                Arguments.of(Variant.NO_FALL_OFF, correct.editRenderer("light.getIlluminationAt(distanceToLight)",
                        "light.getColour().scale(light.getIntensity() / (Math.PI * 4))")),
                Arguments.of(Variant.FALL_OFF_WITHOUT_4PI, correct.editRenderer(
                        "light.getIlluminationAt(distanceToLight)",
                        "light.getColour().scale(light.getIntensity() / Math.pow(distanceToLight, 2))")),
                Arguments.of(Variant.V_AWAY_FROM_CAMERA, correct.editRenderer(
                        "Vector3 V = P.scale(-1).normalised();", "Vector3 V = P.normalised();")),
                Arguments.of(Variant.R_WRONG_WAY, correct.editRenderer("L.reflectIn(N)", "N.reflectIn(L)")),
                Arguments.of(Variant.ROUNDED_BYTES, correct.editRenderer(RGB, "image.setRGB(x, y, "
                        + "(int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.x))) << 16 "
                        + "| (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.y))) << 8 "
                        + "| (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.z))));")),
                Arguments.of(Variant.UPSIDE_DOWN, correct.editRenderer(RGB,
                        "image.setRGB(x, height - 1 - y, linearRGB.toRGB());")),
                Arguments.of(Variant.RED_BLUE_SWAPPED, correct.editRenderer(RGB,
                        "image.setRGB(x, y, new Vector3(linearRGB.z, linearRGB.y, linearRGB.x).toRGB());")),
                Arguments.of(Variant.NORMAL_NOT_NORMALISED, correct.editSphere(
                        "Vector3 normal = this.getNormalAt(point);", "Vector3 normal = point.subtract(position);")),
                Arguments.of(Variant.HIGHLIGHT_COLOURED, correct.editRenderer("Vector3 C_spec = new Vector3(1);",
                        "Vector3 C_spec = C_diff;")),
                Arguments.of(Variant.DIFFUSE_WITHOUT_C_DIFF, correct.editRenderer("C_diff.scale(I).scale(k_d",
                        "I.scale(k_d")),
                Arguments.of(Variant.L_FROM_THE_LIGHT, correct.editRenderer(
                        "light.getPosition().subtract(P).normalised()",
                        "P.subtract(light.getPosition()).normalised()")));
    }
}
