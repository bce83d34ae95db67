package gfx.tick1.command.diff;

import gfx.tick1.command.shared.behaviour.BehaviourCheck;
import gfx.tick1.command.shared.behaviour.DrawnScenes;
import gfx.tick1.command.shared.behaviour.SandboxAhead;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * What {@code tick1 diff} says of the student's methods' behaviour: the two files are compiled
 * with the starter kit and their {@code intersectionWith} and {@code illuminate} are called in
 * the sandbox on the inputs {@code grade} uses (a file not given is the starter kit's, and its
 * method is not reported). For each given file's method, one line first: "behaves as ours on N
 * inputs", or what differs, and a note on each mistake the course's scenes cannot show (the method
 * then does not behave as ours); after the diff, the hints of what to reread. When the methods
 * cannot run (no sandbox, the files do not compile), one line says that behaviour could not be
 * checked. With {@code --no-sandbox} they run without the sandbox.
 */
final class Hints {

    /**
     * The lines before the diff, the lines after it, whether the methods ran, whether they behave as ours, and the
     * handout's scenes as the code drew them (null when not asked for, or the code did not run).
     */
    record Said(List<String> first, List<String> after, boolean ran, boolean behavesAsOurs, DrawnScenes drawn) {
    }

    private Hints() {
    }

    /**
     * What to say of {@code theirs} (class name to source), with {@code starter} for the classes not
     * given, their methods run in the sandbox {@code where} makes; with {@code draw}, the code also draws the
     * handout's scenes.
     */
    static Said of(Map<String, String> theirs, Map<String, String> starter, SandboxAhead where, boolean draw)
            throws InterruptedException {
        String sphere = theirs.getOrDefault("Sphere", starter.get("Sphere"));
        String renderer = theirs.getOrDefault("Renderer", starter.get("Renderer"));
        BehaviourCheck.Lines hints = BehaviourCheck.check(sphere, renderer, List.copyOf(theirs.keySet()), where,
                draw);
        List<String> first = new ArrayList<>(hints.behaviour());
        if (hints.whyNone() != null) {
            first.add(hints.whyNone());
        }
        return new Said(first, hints.hints(), hints.whyNone() == null, hints.behavesAsOurs(),
                hints.drawn());
    }
}
