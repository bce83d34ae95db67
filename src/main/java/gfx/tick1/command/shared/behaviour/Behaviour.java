package gfx.tick1.command.shared.behaviour;

/**
 * The student's two methods compared with ours, input by input: a typed value any report may
 * read (the counterexamples are already in words). {@code ran} is false when the harness logged
 * no answer at all (the code did not compile with the starter's API, or did not get that far).
 */
public record Behaviour(boolean ran, MethodBehaviour intersectionWith, MethodBehaviour illuminate) {

    /**
     * Whether the answers leave {@code mistake} possible: its model gives every tested answer of
     * the method it is a slip of. Any entry is possible when the methods did not run, and an entry
     * of neither method (of render, say) always is.
     */
    public boolean allows(Variant mistake) {
        return !ran || !intersectionWith.ruledOut().contains(mistake) && !illuminate.ruledOut().contains(mistake);
    }

    /**
     * Whether the answers leave {@code entry} possible as the whole of an image: {@link #allows} it, and, for a
     * mistake of render, neither method's answers are visibly what that mistake, drawn with ours, cannot give.
     */
    public boolean allowsAlone(Variant entry) {
        return allows(entry) && (!ran || !intersectionWith.notAlone().contains(entry)
                && !illuminate.notAlone().contains(entry));
    }

    /** Whether both methods behave as ours on every tested input. */
    public boolean behavesAsOurs() {
        return ran && intersectionWith.behavesAsOurs() && illuminate.behavesAsOurs();
    }
}
