package gfx.tick1.command.shared.grader.model;

/**
 * A reason made to fit a limit without cutting a finding: each finding of a grade's reason is a
 * sentence of its own, so a reason too long is cut after the last whole sentence that fits, and a
 * note says where the rest is. Only text with no sentence end in reach (a student's own, never
 * tick1's) is cut inside, with an ellipsis.
 */
public final class FindingText {

    private FindingText() {
    }

    /**
     * {@code text} (null too) when it has at most {@code most} characters; else its whole sentences
     * that fit with {@code rest} after them, then {@code rest}.
     */
    public static String fitted(String text, int most, String rest) {
        if (text == null || text.length() <= most) {
            return text;
        }
        int end = text.lastIndexOf(". ", most - rest.length() - 1);
        if (end > 0) {
            return text.substring(0, end + 1) + rest;
        }
        int cut = most - 1;
        if (Character.isHighSurrogate(text.charAt(cut - 1))) {
            cut--;
        }
        return text.substring(0, cut) + "\u2026";
    }
}
