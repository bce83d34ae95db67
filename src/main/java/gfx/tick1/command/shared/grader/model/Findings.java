package gfx.tick1.command.shared.grader.model;

import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * What a result's explanations found, read back from the lines the grader wrote into them, for the
 * cohort's tallies and comparisons: the catalogue entry that reproduces an image exactly, the facts
 * of the behaviour comparison's tested findings (at a failure), the notes (what a pass noted, and what
 * the course's scenes cannot show), and each wrong scene's difference
 * figures.
 *
 * @param catalogued the title of the first catalogue entry that matches a wrong image exactly, or null
 * @param failed     the facts of the tested findings, at a failure, each once, in order
 * @param notes      the notes: tested findings noted at a pass, and behaviour the course's scenes cannot show
 * @param figures    each wrong image's difference figures, as "scene N: mean difference ...", in scene order
 */
public record Findings(String catalogued, List<String> failed, List<String> notes, List<String> figures) {

    /** How the grader starts the lines read here (SubmissionGrader, ProbeFindings, Diagnosis). */
    private static final String PROBE = "behaviour: ";
    private static final String NOTE = "note: ";
    /** What follows a tested finding's fact when it is noted at a pass (ProbeFindings.notes). */
    private static final String NOT_TESTED = " (tick1.xml and the hidden scene do not show this";
    private static final String FIGURES = "mean difference ";
    private static final String VERDICT = "verdict: ";
    private static final String EXACTLY = ": every pixel matches it exactly.";

    public Findings {
        failed = List.copyOf(failed);
        notes = List.copyOf(notes);
        figures = List.copyOf(figures);
    }

    /** The findings of {@code result}'s explanations. */
    public static Findings of(StudentResult result) {
        String catalogued = null;
        Set<String> failed = new LinkedHashSet<>();
        Set<String> notes = new LinkedHashSet<>();
        List<String> figures = new ArrayList<>();
        int scene = 0;
        for (SceneResult each : result.scenes()) {
            scene++;
            for (String line : each.explanation()) {
                if (line.startsWith(PROBE)) {
                    failed.add(line.substring(PROBE.length()));
                } else if (line.startsWith(NOTE)) {
                    int end = line.indexOf(NOT_TESTED);
                    notes.add(line.substring(NOTE.length(), end < 0 ? line.length() : end));
                } else if (line.startsWith(FIGURES)) {
                    figures.add("scene " + scene + ": " + line);
                } else if (catalogued == null && line.startsWith(VERDICT) && line.endsWith(EXACTLY)) {
                    catalogued = line.substring(VERDICT.length(), line.length() - EXACTLY.length());
                }
            }
        }
        return new Findings(catalogued, List.copyOf(failed), List.copyOf(notes), figures);
    }
}
