package gfx.tick1.diff;

import gfx.tick1.grade.grading.CodeProbe;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The hints of {@code tick1 diff}: only facts that a probe of the student's own methods showed.
 * The two files are compiled with the starter kit and their {@code intersectionWith} and
 * {@code illuminate} are called in the sandbox on the fixed inputs {@code grade} uses (a file not
 * given is the starter kit's, and its method's probes are not reported); each failed probe of a
 * given file's method is one hint. When the probes cannot run (no sandbox, the files do not
 * compile), there are no hints, and one line says why.
 */
final class Hints {

    private Hints() {
    }

    /**
     * The hint lines for {@code theirs} (class name to source), with {@code starter} for the
     * classes not given: "hint: ..." lines, or one "no hints: ..." line, or none when every probe holds.
     */
    static List<String> of(Map<String, String> theirs, Map<String, String> starter) throws InterruptedException {
        String sphere = theirs.getOrDefault("Sphere", starter.get("Sphere"));
        String renderer = theirs.getOrDefault("Renderer", starter.get("Renderer"));
        CodeProbe.Hints hints = CodeProbe.probe(sphere, renderer, List.copyOf(theirs.keySet()));
        List<String> lines = new ArrayList<>();
        if (hints.whyNone() != null) {
            lines.add(hints.whyNone());
        }
        hints.hints().forEach(hint -> lines.add("hint: " + hint));
        return lines;
    }
}
