package gfx.tick1.command.bench;

import gfx.tick1.command.shared.kit.StarterKit;

/**
 * The two Renderer.java a student hands in, for the benchmark's one-student section, made from the course's solution
 * ({@link StarterKit#solution}): a correct one in the student's own words, and one with the commonest slip. Each
 * changes one expression, which must be in the solution: a solution written otherwise fails the benchmark with that
 * expression's name rather than time something else.
 */
final class StudentSolutions {

    /** The diffuse term's factor as the course's solution writes it. */
    static final String DIFFUSE = "k_d * Math.max(0, NdotL)";
    /**
     * The same product the other way round: every pixel the same (a product of two doubles does not depend on their
     * order), but a difference {@code tick1 diff} shows and then runs the methods on.
     */
    static final String DIFFUSE_OWN_WORDS = "Math.max(0, NdotL) * k_d";
    /** N.L not clamped: the diffuse term goes negative where the light is behind the surface. */
    static final String DIFFUSE_NOT_CLAMPED = "k_d * NdotL";

    private StudentSolutions() {
    }

    /** The course's Renderer.java with its diffuse factor written as a student might: correct, not the same text. */
    static String correctRenderer() {
        return changed(DIFFUSE_OWN_WORDS);
    }

    /** The course's Renderer.java with N.L not clamped: a wrong image, which the grade explains. */
    static String wrongRenderer() {
        return changed(DIFFUSE_NOT_CLAMPED);
    }

    private static String changed(String diffuse) {
        String solution = StarterKit.solution("Renderer");
        if (!solution.contains(DIFFUSE)) {
            throw new IllegalStateException("the course's Renderer.java no longer writes " + DIFFUSE);
        }
        return solution.replace(DIFFUSE, diffuse);
    }
}
