package gfx.tick1.command.shared.grader.lookalike;

import gfx.tick1.command.shared.grader.model.Submission;

/**
 * Two submissions that look alike, or one that looks like tick1's reference, and why.
 *
 * @param a        the first submission
 * @param b        the second, or null for tick1's reference
 * @param reason   why the pair is listed
 * @param why      the reason in one short phrase, for a person
 * @param compared their code as compared, and the runs it shares
 */
public record Lookalike(Submission a, Submission b, Reason reason, String why, Comparison compared) {

    /** Why a pair is listed, strongest evidence first. */
    public enum Reason {
        /** The two methods are tick1's reference's, in tokens after renaming. */
        REFERENCE,
        /** Most tokens lie in shared runs, after renaming and with the starter code set aside. */
        TOKENS,
        /** The same wrong answers, of a mistake no catalogue entry or probe names. */
        SAME_UNCATALOGUED_ANSWERS,
        /** The same wrong answers, of a mistake few in the cohort made. */
        SAME_WRONG_ANSWERS
    }

    /** The share of both sides' tokens that lie in shared runs: see {@link Comparison#similarity()}. */
    public double similarity() {
        return compared.similarity();
    }
}
