package gfx.tick1.command.shared.grader.model;

import java.io.IOException;

/**
 * A cohort's download or grading worksheet that cannot be used as a whole: an unreadable file, a file that is not a
 * zip, a hostile archive, a malformed worksheet. The message is the one line the command prints: it names the file
 * (and, for a worksheet, the line) and says what was wrong.
 */
public final class CohortInputException extends IOException {

    private static final long serialVersionUID = 1L;

    public CohortInputException(String message) {
        super(message);
    }
}
