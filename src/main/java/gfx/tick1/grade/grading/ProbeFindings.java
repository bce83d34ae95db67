package gfx.tick1.grade.grading;

import gfx.tick1.grade.grading.ProbeJudge.Judgement;
import gfx.tick1.grade.grading.ProbeJudge.State;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * What the probes found, in the words every report uses: the facts of the failed probes (the
 * reasons of a failure, the notes of a pass), one short sentence for a gradebook row, and the
 * sections to reread, at most three.
 */
final class ProbeFindings {

    /** The most facts a row's sentence names; the rest are counted. */
    private static final int ROW_FACTS = 3;
    /** The most sections a report lists to reread. */
    static final int SECTIONS = 3;

    private final boolean ran;
    private final List<Judgement> failed;

    private ProbeFindings(boolean ran, List<Judgement> failed) {
        this.ran = ran;
        this.failed = failed;
    }

    /** The findings of the probes' log {@code log} (null when the child left none). */
    static ProbeFindings of(String log) {
        ProbeAnswers answers = ProbeAnswers.parse(log);
        if (!answers.any()) {
            return new ProbeFindings(false, List.of());
        }
        return new ProbeFindings(true, ProbeJudge.judge(answers).stream().filter(j -> j.state() == State.FAILS)
                .toList());
    }

    /** Whether the probes ran (the child logged answers). */
    boolean ran() {
        return ran;
    }

    /** The failed probes. */
    List<Probe> failedProbes() {
        return failed.stream().map(Judgement::probe).toList();
    }

    /** The failed probes' judgements, in the catalogue's order. */
    List<Judgement> failed() {
        return failed;
    }

    boolean anyFailed() {
        return !failed.isEmpty();
    }

    /** The facts of the failed probes, one a line. */
    List<String> facts() {
        return failed.stream().map(Judgement::fact).toList();
    }

    /** "fact (section ...)" lines for a failure's explanation, then "reread: handout ..." lines. */
    List<String> failureLines() {
        List<String> lines = new ArrayList<>();
        failed.forEach(j -> lines.add("probe: " + j.fact()));
        sections().forEach(section -> lines.add("reread: handout " + section));
        return lines;
    }

    /** The notes of a pass: each failed probe's fact, that the course does not test it, and why it may not matter. */
    List<String> notes() {
        List<String> notes = new ArrayList<>();
        for (Judgement j : failed) {
            String leftOpen = j.probe().leftOpen();
            notes.add(j.fact() + "; the course's scenes do not test this" + (leftOpen == null ? "" : "; " + leftOpen)
                    + " (handout " + j.section() + ")");
        }
        return notes;
    }

    /** The failed probes' sections, each once, at most {@link #SECTIONS}. */
    List<String> sections() {
        Set<String> sections = new LinkedHashSet<>();
        failed.forEach(j -> sections.add(j.section()));
        return sections.stream().limit(SECTIONS).toList();
    }

    /** The facts in one sentence for a row: "a; b; and 2 more." */
    String sentence() {
        List<String> facts = facts();
        StringBuilder text = new StringBuilder(capitalised(String.join("; ", facts.subList(0,
                Math.min(ROW_FACTS, facts.size())))));
        if (facts.size() > ROW_FACTS) {
            text.append("; and ").append(facts.size() - ROW_FACTS).append(" more (see the feedback)");
        }
        return text.append('.').toString();
    }

    static String capitalised(String text) {
        return text.isEmpty() ? text : Character.toUpperCase(text.charAt(0)) + text.substring(1);
    }
}
