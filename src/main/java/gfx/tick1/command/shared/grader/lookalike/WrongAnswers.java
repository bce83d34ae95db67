package gfx.tick1.command.shared.grader.lookalike;

import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult;
import java.util.ArrayList;
import java.util.List;

/**
 * What a failed submission's methods got wrong, as a fingerprint: two submissions with equal
 * answers gave the same wrong answers on the same inputs. Made today from the {@link Findings} a
 * result's grade made: the failed probes' facts (what the methods returned on tick1's inputs) and each
 * wrong scene's difference figures (equal figures on every scene: the same wrong image). A
 * comparison of the methods' answers on inputs of its own can make one through the constructor.
 *
 * @param answers    the wrong answers, each a line equal for equal answers, in a fixed order
 * @param catalogued the catalogue entry whose model reproduces the answers exactly, or null
 * @param named      a short name of the first wrong answer a probe names ("illuminate: N.L not
 *                   clamped"), or null when no probe names one
 */
public record WrongAnswers(List<String> answers, String catalogued, String named) {

    public WrongAnswers {
        answers = List.copyOf(answers);
    }

    /** The fingerprint of a failed result's wrong answers, or null: it passed, or gave no wrong answer (a crash). */
    public static WrongAnswers of(StudentResult result) {
        if (result.passed()) {
            return null;
        }
        Findings findings = result.findings();
        List<String> answers = new ArrayList<>(findings.failed());
        answers.addAll(findings.figures());
        return answers.isEmpty() ? null : new WrongAnswers(answers,
                findings.catalogued() == null ? null : findings.catalogued().title(),
                findings.failed().isEmpty() ? null : result.diagnosis().label());
    }

    /** Whether a catalogue entry or a probe names the mistake. */
    public boolean isNamed() {
        return catalogued != null || named != null;
    }

    /** "the same wrong answers: far root", or "the same uncatalogued wrong answer". */
    public String why() {
        return !isNamed() ? "the same uncatalogued wrong answer"
                : "the same wrong answers: " + (catalogued != null ? catalogued : named);
    }
}
