package gfx.tick1.command.shared.grader.model;

/**
 * Findings as long as tick1 writes them for a student whose two methods are both wrong in ways
 * the catalogue does not know: counterexamples with every digit, and the answers' properties.
 */
public final class LongFindings {

    /** intersectionWith's finding, ending in its last words. */
    public static final String INTERSECTION = "your intersectionWith differs from ours on 212 of 1008 inputs; the "
            + "simplest: for a ray from (0.1234567891, -0.9876543211, 0.5555555551) along (0.3333333331, "
            + "0.6666666661, -0.9999999991) and a sphere at (1.2345678911, 2.3456789121, 3.4567891231) of radius "
            + "0.7777777771, yours returns a hit at s = 3.1415926535 at (1.1506543198, 1.1066106351, "
            + "-2.5860371035) with normal (0.1234567890, 0.2345678901, 0.9641411761); ours returns a hit at s = "
            + "2.7182818284 at (1.0294840326, 0.8245349237, -2.1627262731) with normal (-0.2631578947, "
            + "-0.6842105263, 0.6803842646); your hits are farther than ours; tick1 does not recognise this mistake";
    /** illuminate's finding. */
    public static final String ILLUMINATE = "your illuminate differs from ours on 480 of 1002 inputs; the simplest: "
            + "for a point (0.2500000001, -0.5000000001, 4.7500000001) with normal (0.4472135955, 0, 0.8944271910), "
            + "a light at (3.0000000001, 4.0000000001, -2.0000000001) of colour (1, 0.9, 0.8) and intensity "
            + "123.4567890123, ambient (0.05, 0.05, 0.05) and a sphere of colour (0.8, 0.1, 0.1), yours returns "
            + "the colour (0.3141592653, 0.0271828182, 0.0161803398); ours returns the colour (0.2718281828, "
            + "0.0314159265, 0.0141421356); your colours are brighter than ours where the light is far; tick1 does "
            + "not recognise this mistake";
    /** The line that sends the student to the handout. */
    public static final String REREAD = "reread: handout section 4, \"Ray-sphere intersection code\"; "
            + "handout section 5, \"Phong illumination code\"";
    /** The reason's first sentences, before the findings. */
    public static final String HEAD = "FAILED: 1 of 1 scene wrong. tick1.xml: 98343 pixels differ.";
    /** A failure's reason with both findings, as the grader words it: a sentence each. */
    public static final String REASON = HEAD + " " + sentence(INTERSECTION) + " " + sentence(ILLUMINATE);

    private LongFindings() {
    }

    /** A finding as a sentence of a reason. */
    public static String sentence(String finding) {
        return Character.toUpperCase(finding.charAt(0)) + finding.substring(1) + ".";
    }
}
