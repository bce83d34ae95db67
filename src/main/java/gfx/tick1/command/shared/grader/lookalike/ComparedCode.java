package gfx.tick1.command.shared.grader.lookalike;

import java.util.ArrayList;
import java.util.List;

/**
 * One side of a comparison: the members compared (the two methods the tick asks for and any member
 * the student added), each as its canonical text, and the tokens of that text. Tokens that belong
 * to the starter code (the base) are set aside: no tile holds them, and they do not count.
 */
public final class ComparedCode {

    /**
     * A member compared.
     *
     * @param file      the file it is in, "Sphere.java" or "Renderer.java"
     * @param signature its signature, "intersectionWith(Ray)"
     * @param text      its canonical text: one statement a line, no comments, locals named #1, #2, ...
     */
    public record Member(String file, String signature, String text) {
    }

    /** What kind of text a span of a member's text is on the side-by-side page. */
    public enum Kind {
        /** Tokens in a run both sides share. */
        SHARED,
        /** Tokens of the starter code, which every student was given. */
        BASE
    }

    /** A marked span of a member's text, {@code [start, end)}. */
    public record Span(int start, int end, Kind kind) {
    }

    /**
     * The tokens of a side, each at the same index of the four: its word (an index into the
     * vocabulary), the member it is in, and where it starts and ends in that member's text.
     */
    record Tokens(int[] words, int[] memberOf, int[] starts, int[] ends) {
    }

    private final List<Member> members;
    private final List<String> notes;
    /** Each token's index into the vocabulary, the member it is in, and its span in that member's text. */
    final int[] tokens;
    private final int[] memberOf;
    private final int[] starts;
    private final int[] ends;
    final GreedyStringTiling.Sequence sequence;

    /** The side of {@code members} and {@code tokens}; {@code base} marks the tokens set aside. */
    ComparedCode(List<Member> members, List<String> notes, Tokens tokens, boolean[] base, int minimum) {
        this.members = List.copyOf(members);
        this.notes = List.copyOf(notes);
        this.tokens = tokens.words();
        this.memberOf = tokens.memberOf();
        this.starts = tokens.starts();
        this.ends = tokens.ends();
        this.sequence = new GreedyStringTiling.Sequence(this.tokens, base, minimum);
    }

    public List<Member> members() {
        return members;
    }

    /** What was not compared and why ("Sphere.java does not parse"), one phrase each; empty when all was. */
    public List<String> notes() {
        return notes;
    }

    /** How many tokens count: those not of the base. */
    public int counted() {
        return sequence.counted();
    }

    /**
     * The marked spans of each member's text (in {@link #members}' order): the runs of tokens in
     * {@code shared} (true for a token in a tile), and the base's tokens; each span covers whole
     * tokens and the white space between two of the same kind.
     */
    public List<List<Span>> spans(boolean[] shared) {
        List<List<Span>> spans = new ArrayList<>();
        members.forEach(member -> spans.add(new ArrayList<>()));
        for (int t = 0; t < tokens.length; t++) {
            Kind kind = shared[t] ? Kind.SHARED : sequence.setAside[t] ? Kind.BASE : null;
            if (kind == null) {
                continue;
            }
            List<Span> ofMember = spans.get(memberOf[t]);
            Span last = ofMember.isEmpty() ? null : ofMember.get(ofMember.size() - 1);
            boolean continues = last != null && last.kind() == kind && t > 0 && memberOf[t - 1] == memberOf[t]
                    && last.end() == ends[t - 1] && (shared[t - 1] ? Kind.SHARED
                            : sequence.setAside[t - 1] ? Kind.BASE : null) == kind;
            if (continues) {
                ofMember.set(ofMember.size() - 1, new Span(last.start(), ends[t], kind));
            } else {
                ofMember.add(new Span(starts[t], ends[t], kind));
            }
        }
        return spans;
    }

    /** How many tokens there are, base included. */
    int length() {
        return tokens.length;
    }
}
