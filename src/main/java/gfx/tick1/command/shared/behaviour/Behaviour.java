package gfx.tick1.command.shared.behaviour;

/**
 * The student's two methods compared with ours, input by input: a typed value any report may
 * read (the counterexamples are already in words). {@code ran} is false when the harness logged
 * no answer at all (the code did not compile with the starter's API, or did not get that far).
 */
public record Behaviour(boolean ran, MethodBehaviour intersectionWith, MethodBehaviour illuminate) {

    /** Whether both methods behave as ours on every tested input. */
    public boolean behavesAsOurs() {
        return ran && intersectionWith.behavesAsOurs() && illuminate.behavesAsOurs();
    }
}
