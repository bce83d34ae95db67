package gfx.tick1.diff;

import gfx.tick1.diagnose.Variant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import java.util.regex.Pattern;

/**
 * Which entries of the diagnose catalogue a difference in one member looks like: each rule reads
 * the lines of ours that the student's version does not have (removed) and the lines of theirs
 * that ours does not have (added), as {@link JavaMembers} prints them.
 */
final class Hints {

    /** The changed lines of one member, and the whole of the student's version of it. */
    record Change(String member, List<String> removed, List<String> added, List<String> theirs) {

        boolean removes(String regex) {
            return any(removed, regex);
        }

        boolean has(String regex) {
            return any(theirs, regex);
        }

        boolean adds(String regex) {
            return any(added, regex);
        }

        private static boolean any(List<String> lines, String regex) {
            Predicate<String> found = Pattern.compile(regex).asPredicate();
            return lines.stream().anyMatch(found);
        }
    }

    private record Rule(Variant variant, String member, Predicate<Change> applies) {
    }

    private static final String NUMBER = "\\s*[-+]?[\\d.]+";

    private static final List<Rule> RULES = List.of(
            new Rule(Variant.BACKGROUND_ONLY, "intersectionWith(Ray)",
                    c -> c.removes("new RaycastHit\\(this,") && !c.adds("new RaycastHit\\(this,")),
            new Rule(Variant.FAR_ROOT, "intersectionWith(Ray)",
                    c -> c.removes("s1 > 0 \\? s1 : s2") && c.adds("\\bs = s2;")),
            new Rule(Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT, "intersectionWith(Ray)",
                    c -> c.adds("s1 <=? 0 \\|\\| s2 <=? 0|s2 <=? 0 \\|\\| s1 <=? 0")),
            new Rule(Variant.UNCHECKED_NEGATIVE_SQUARE_ROOT, "intersectionWith(Ray)",
                    c -> c.removes("if \\(discriminant < 0\\)") && c.has("Math\\.sqrt\\(")
                            && !c.adds("discriminant\\s*(<|>=|<=|>)" + NUMBER)),
            new Rule(Variant.FLAT_COLOUR, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.adds("return object\\.getColour\\(\\);")),
            new Rule(Variant.AMBIENT_ONLY, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.adds("return ambient;")),
            new Rule(Variant.AMBIENT_DIFFUSE, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.adds("return (ambient\\.add\\(diffuse\\)|diffuse\\.add\\(ambient\\));")),
            new Rule(Variant.AMBIENT_WITHOUT_C_DIFF, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.adds("\\bambient = I_a;")),
            new Rule(Variant.SPECULAR_WITHOUT_I, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.removes("specular = C_spec\\.scale\\(I\\)") && c.adds("specular = ")
                            && !c.adds("specular = .*\\bI\\b")),
            new Rule(Variant.UNNORMALISED_L_V, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.adds("Vector3 [LV] = (?!.*normalised\\(\\)).*;")
                            && !c.adds("Vector3 V = P\\.normalised\\(\\)")),
            new Rule(Variant.V_AWAY_FROM_CAMERA, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.adds("Vector3 V = P\\.normalised\\(\\)")),
            new Rule(Variant.R_WRONG_WAY, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.adds("N\\.reflectIn\\(L\\)")),
            new Rule(Variant.UNCLAMPED_N_DOT_L, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.removes("Math\\.max\\(0, NdotL\\)") && c.adds("NdotL") && !c.adds(clamped("NdotL"))),
            new Rule(Variant.UNCLAMPED_R_DOT_V, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.removes("Math\\.max\\(0, RdotV\\)") && c.adds("RdotV") && !c.adds(clamped("RdotV"))),
            new Rule(Variant.NO_FALL_OFF, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.removes("getIlluminationAt\\(distanceToLight\\)") && c.adds("getIntensity\\(\\)")
                            && !c.adds("getIntensity\\(\\).*distanceToLight")),
            new Rule(Variant.FALL_OFF_WITHOUT_4PI, "illuminate(Scene, Sphere, Vector3, Vector3)",
                    c -> c.removes("getIlluminationAt\\(distanceToLight\\)")
                            && c.adds("getIntensity\\(\\).*distanceToLight") && !c.adds("Math\\.PI")),
            new Rule(Variant.ROUNDED_BYTES, "render(Scene)", c -> c.adds("Math\\.round\\(")),
            new Rule(Variant.UPSIDE_DOWN, "render(Scene)", c -> c.adds("height - 1 - y|height - y - 1")),
            new Rule(Variant.RED_BLUE_SWAPPED, "render(Scene)", c -> c.adds("\\.z, \\w+\\.y, \\w+\\.x")));

    private Hints() {
    }

    /** max(0, x) or max(x, 0), with 0 or 0.0. */
    private static String clamped(String x) {
        return "max\\((0|0\\.0), " + x + "\\)|max\\(" + x + ", (0|0\\.0)\\)";
    }

    /** The catalogue entries the change looks like, in the catalogue's order of rules. */
    static List<Variant> of(Change change) {
        List<Variant> hints = new ArrayList<>();
        for (Rule rule : RULES) {
            if (rule.member().equals(change.member()) && rule.applies().test(change)) {
                hints.add(rule.variant());
            }
        }
        return hints;
    }
}
