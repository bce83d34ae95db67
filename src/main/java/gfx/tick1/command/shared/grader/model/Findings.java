package gfx.tick1.command.shared.grader.model;

import gfx.tick1.command.shared.behaviour.Variant;
import java.util.List;
import java.util.function.UnaryOperator;

/**
 * What a grade found, kept beside its words for the cohort's tallies and comparisons: the catalogue
 * entry that reproduces a wrong image exactly, the tested facts of the behaviour comparison (at a
 * pass too, where the course's scenes do not show them), the notes on what the course's scenes
 * cannot show, each wrong scene's difference figures, and the handout sections it sends the student
 * to reread. The grader makes
 * them as it explains each scene; nothing reads them back from the explanation's lines.
 *
 * @param catalogued the first catalogue entry that a wrong image is exactly, or null when none is
 * @param failed     the behaviour comparison's tested facts (the probes a method failed), each once, in order
 * @param notes      the notes on behaviour the course's scenes cannot show, each once, in order
 * @param figures    each wrong image's difference figures, as "scene N: mean difference ...", in scene order
 * @param reread     the handout sections the explanations name to reread, as "handout section 5 ...", in order
 */
public record Findings(Variant catalogued, List<String> failed, List<String> notes, List<String> figures,
        List<String> reread) {

    /** A result with nothing found: a pass with nothing to note, or code that never rendered. */
    public static final Findings NONE = new Findings(null, List.of(), List.of(), List.of(), List.of());

    public Findings {
        failed = List.copyOf(failed);
        notes = List.copyOf(notes);
        figures = List.copyOf(figures);
        reread = List.copyOf(reread);
    }

    /** These findings with each fact, note, figure and section passed through {@code text} (to bound it, say). */
    public Findings mapText(UnaryOperator<String> text) {
        return new Findings(catalogued, failed.stream().map(text).toList(), notes.stream().map(text).toList(),
                figures.stream().map(text).toList(), reread.stream().map(text).toList());
    }
}
