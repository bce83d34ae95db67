package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.StudentResult;

/**
 * Where a result stands in the report: passed, failed, or not graded (tick1 could not grade it, so
 * there is no verdict on the code: never shown or counted as a fail).
 */
enum Standing {
    PASSED("pass", "pass"),
    FAILED("fail", "fail"),
    NOT_GRADED("not-graded", "not graded");

    /** The class the report's pages style it by. */
    private final String style;
    /** How a row's result cell says it. */
    private final String words;

    Standing(String style, String words) {
        this.style = style;
        this.words = words;
    }

    static Standing of(StudentResult result) {
        return !result.graded() ? NOT_GRADED : result.passed() ? PASSED : FAILED;
    }

    String style() {
        return style;
    }

    String words() {
        return words;
    }
}
