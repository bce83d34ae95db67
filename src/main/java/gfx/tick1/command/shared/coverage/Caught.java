package gfx.tick1.command.shared.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import java.util.List;

/**
 * One catalogued mistake, or two made together, and how many pixels its image of each scene
 * differs by from the image a pass needs (the fewer of the two references {@code grade} accepts).
 * A scene catches it when at least one pixel differs: the course's tester wants every pixel equal.
 *
 * @param entries the catalogue's entries made: one, or two together
 * @param pixels  pixels differing, scene by scene in the order of the coverage's scenes
 */
public record Caught(List<Variant> entries, List<Long> pixels) {

    public Caught {
        entries = List.copyOf(entries);
        pixels = List.copyOf(pixels);
    }

    /** "far root", or for two together "far root" with "normal not normalised", as {@code grade} names them. */
    public String title() {
        return entries.size() == 1 ? entries.get(0).title()
                : "\"" + String.join("\" with \"", entries.stream().map(Variant::title).toList()) + "\"";
    }

    /** Whether scene {@code index} catches it. */
    public boolean caughtBy(int index) {
        return pixels.get(index) > 0;
    }

    /** Whether any scene catches it. */
    public boolean caught() {
        return total() > 0;
    }

    /** The pixels differing on all the scenes together. */
    public long total() {
        return pixels.stream().mapToLong(Long::longValue).sum();
    }
}
