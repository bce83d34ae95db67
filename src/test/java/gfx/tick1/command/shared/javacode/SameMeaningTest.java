package gfx.tick1.command.shared.javacode;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Which two members {@code tick1 diff} counts as meaning the same: only those equal up to
 * parentheses, {@code this.} on an unshadowed field, consistent renaming and the order of
 * independent declarations; every other change, however small, is a difference.
 */
class SameMeaningTest {

    /** A class with fields f, g and u, two methods of its own, and {@code method}. */
    private static JavaMembers parse(String method, JavaMembers like) throws JavaMembers.ParseException {
        return JavaMembers.parse("T.java", "class T { private double f, g; private Vector3 u; "
                + "double next() { return 1; } double other() { return 2; } " + method + " }", like);
    }

    private static String key(JavaMembers members) {
        return members.members().get("m" + members.members().keySet().stream().filter(s -> s.startsWith("m("))
                .findFirst().orElseThrow().substring(1)).key();
    }

    /** The canonical texts of our method and of theirs, as diff compares them. */
    private static String[] keys(String ours, String theirs) throws JavaMembers.ParseException {
        JavaMembers our = parse(ours, null);
        return new String[] {key(our), key(parse(theirs, our))};
    }

    @ParameterizedTest(name = "{0} == {1}")
    @CsvSource(delimiter = '|', value = {
        "double m(double a, double b, double c) { return (a + b) * c; }"
            + " | double m(double a, double b, double c) { return ((a + b)) * (c); }",
        "double m(double a, double b, double c) { return a * b + c; }"
            + " | double m(double a, double b, double c) { return (a * b) + c; }",
        "double m(Vector3 O, Vector3 C) { return (O.subtract(C)).dot(O); }"
            + " | double m(Vector3 O, Vector3 C) { return O.subtract(C).dot(O); }",
        "double m() { double x = this.f; return x; } | double m() { double x = f; return x; }",
        "double m() { double x = f; return x * 2; } | double m() { double y = f; return y * 2; }",
        "double m(double a) { return a; } | double m(double value) { return value; }",
        "double m(double a) { return - -a; } | double m(double a) { return -(-a); }",
        "void m(double v) { f = v; } | void m(double f) { this.f = f; }",
        "double m() { double f = this.f; return f; } | double m() { double x = f; return x; }",
        "double m() { double p = Math.sqrt(f); double q = Math.abs(g); return p - q; }"
            + " | double m() { double q = Math.abs(g); double p = Math.sqrt(f); return p - q; }",
        "double m(Vector3 P) { Vector3 L = u.subtract(P).normalised(); Vector3 V = P.scale(-1).normalised();"
            + " return L.dot(V); } | double m(Vector3 P) { Vector3 V = P.scale(-1).normalised();"
            + " Vector3 L = u.subtract(P).normalised(); return L.dot(V); }",
        "void m(boolean c) { if (c) { double t = 1; f = t; } else { double t = 2; f = t; } }"
            + " | void m(boolean c) { if (c) { double x = 1; f = x; } else { double y = 2; f = y; } }",
        "double m() { double a = f; double b = g; return a - b; }"
            + " | double m() { double b = f; double a = g; return b - a; }",
        "double m() { double x = f; return x; } | double m() { final double x = f; return x; }",
        "double m(double a) { return a; } | double m(final double a) { return a; }",
        "double m() { double x = f; return x; } | double m() { @Deprecated final double y = f; return y; }",
        "double m() { double p = Math.sqrt(f); double q = Math.abs(g); return p - q; }"
            + " | double m() { final double q = Math.abs(g); final double p = Math.sqrt(f); return p - q; }"})
    void membersEqualUpToWhatCannotChangeTheirMeaningHaveOneKey(String ours, String theirs) throws Exception {
        String[] keys = keys(ours, theirs);
        assertThat(keys[1]).as(theirs).isEqualTo(keys[0]);
    }

    @ParameterizedTest(name = "{0} != {1}")
    @CsvSource(delimiter = '|', value = {
        "double m(double a, double b, double c) { return (a + b) * c; }"
            + " | double m(double a, double b, double c) { return a + b * c; }",
        "double m(double a, double b, double c) { return a - (b - c); }"
            + " | double m(double a, double b, double c) { return a - b - c; }",
        "int m(double a, double b) { return (int) (a + b); } | int m(double a, double b) { return (int) a + b; }",
        "double m(double a, double b) { return -a * b; } | double m(double a, double b) { return -(a * b); }",
        "void m(double f) { this.f = f; } | void m(double f) { f = f; }",
        "double m() { double x = f; double y = g; return x - y; }"
            + " | double m() { double x = f; double y = g; return y - x; }",
        "double m() { double y = f; double f = 2; return y + f; }"
            + " | double m() { double f = 2; double y = f; return y + f; }",
        "double m() { double a = next(); double b = other(); return a - b; }"
            + " | double m() { double b = other(); double a = next(); return a - b; }",
        "double m() { double a = f; return a; } | double m() { double a = g; return a; }",
        "double m() { return Math.max(0, f); } | double m() { return Math.max(0.0, f); }",
        "double m(double a, double b) { return a + b; } | double m(double a, double b) { return b + a; }"})
    void everyOtherChangeIsADifference(String ours, String theirs) throws Exception {
        String[] keys = keys(ours, theirs);
        assertThat(keys[1]).as(theirs).isNotEqualTo(keys[0]);
    }
}
