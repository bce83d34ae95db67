package gfx.tick1.command.shared.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.IntStream;

/**
 * Which catalogued mistakes a set of grading scenes catches: for each mistake and scene the
 * pixels its image differs by, at one image size; for the mistakes none catches, the reason where
 * tick1 knows one; and the pairs of mistakes {@code grade} names together that some scene
 * catches neither of alone.
 *
 * @param scenes   the scenes' names, in the order of every {@link Caught#pixels()}
 * @param mistakes each mistake of the catalogue alone, in the catalogue's order
 * @param pairs    each pair of entries of one method that some scene catches neither of alone
 * @param reasons  why no scene catches a mistake, for the missed ones tick1 knows a reason for
 * @param sixSteps the handout's six steps taken literally, a correct answer: a scene that "catches" it
 *                 fails a correct answer (a ray starts inside a sphere or on its surface, or grazes one)
 */
public record Coverage(List<String> scenes, int width, int height, List<Caught> mistakes, List<Caught> pairs,
        Map<Variant, KnownReason> reasons, Caught sixSteps) {

    public Coverage {
        scenes = List.copyOf(scenes);
        mistakes = List.copyOf(mistakes);
        pairs = List.copyOf(pairs);
        reasons = Map.copyOf(reasons);
    }

    /** The mistakes at least one scene catches. */
    public Set<Variant> caught() {
        Set<Variant> caught = EnumSet.noneOf(Variant.class);
        mistakes.stream().filter(Caught::caught).forEach(mistake -> caught.add(mistake.entries().get(0)));
        return caught;
    }

    /** The mistakes scene {@code index} catches. */
    public Set<Variant> caughtBy(int index) {
        Set<Variant> caught = EnumSet.noneOf(Variant.class);
        mistakes.stream().filter(mistake -> mistake.caughtBy(index))
                .forEach(mistake -> caught.add(mistake.entries().get(0)));
        return caught;
    }

    /** The mistakes scene {@code index} catches and no other scene does. */
    public List<Variant> caughtOnlyBy(int index) {
        List<Variant> only = new ArrayList<>();
        for (Caught mistake : mistakes) {
            if (mistake.caughtBy(index) && IntStream.range(0, scenes.size())
                    .noneMatch(other -> other != index && mistake.caughtBy(other))) {
                only.add(mistake.entries().get(0));
            }
        }
        return only;
    }

    /** The mistakes no scene catches, in the catalogue's order. */
    public List<Variant> missed() {
        return mistakes.stream().filter(mistake -> !mistake.caught()).map(mistake -> mistake.entries().get(0))
                .toList();
    }

    /** Why no scene catches {@code mistake}, if tick1 knows. */
    public Optional<KnownReason> reason(Variant mistake) {
        return Optional.ofNullable(reasons.get(mistake));
    }

    /** The row of one mistake alone. */
    public Caught of(Variant mistake) {
        return mistakes.stream().filter(row -> row.entries().equals(List.of(mistake))).findFirst()
                .orElseThrow(() -> new IllegalArgumentException(mistake + " is not a catalogued mistake"));
    }
}
