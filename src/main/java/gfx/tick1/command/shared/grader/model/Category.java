package gfx.tick1.command.shared.grader.model;

/**
 * The cohort's category of one submission, for the chart of common failures and the students'
 * table: a kind of outcome the grader knows by its type, or a mistake named by the catalogue or
 * the behaviour comparison. The words are the label's alone; no code decides anything from them.
 */
public sealed interface Category {

    /** The words the chart and the table show. */
    String label();

    /** An outcome the grader knows without naming a mistake. */
    enum Outcome implements Category {
        PASSED("passed"),
        SUBMISSION_PROBLEM("submission problem"),
        NOT_UTF8("not UTF-8"),
        WRONG_PACKAGE("wrong package"),
        DOES_NOT_COMPILE("does not compile"),
        TIME_LIMIT("time limit"),
        EXCEPTION("exception"),
        CRASHED("crashed or exited"),
        UNRECOGNISED("unrecognised mistake"),
        NOT_FROM_THE_CODE("image not from the code"),
        /** tick1 could not grade the submission: its grader failed, not its code. */
        NOT_GRADED("not graded");

        private final String label;

        Outcome(String label) {
            this.label = label;
        }

        @Override
        public String label() {
            return label;
        }
    }

    /**
     * A wrong image's mistake, by name: the catalogue entry it is exactly, or the first tested
     * finding's label ("illuminate: N.L not clamped").
     */
    record Mistake(String label) implements Category {
    }
}
