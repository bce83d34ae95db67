package gfx.tick1.command.shared.cli;

/**
 * A command that cannot go on: the exit status and the one line that says why. Thrown from a command's
 * {@code call()}; tick1's start-up prints it once, after the command's name ({@code tick1 grade: ...}), on the
 * command's standard error, and exits with the status. So no command formats its own error lines.
 */
public final class CommandFailure extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final int status;

    /**
     * @param status the exit status, one the command lists in its help
     * @param line   what went wrong and what was expected, without the command's name
     */
    public CommandFailure(int status, String line) {
        super(line, null, false, false);   // no stack trace: it is never shown
        this.status = status;
    }

    public int status() {
        return status;
    }
}
