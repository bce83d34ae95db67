package gfx.tick1.command.shared.cli;

/**
 * The program's entry point by name, for code that starts tick1 in a fresh process ({@code tick1
 * bench}). A name, not a class reference: no command may depend on the entry point, which
 * depends on every command.
 */
public final class MainClass {

    /** The class whose {@code main} starts tick1; a test checks it against the class. */
    public static final String NAME = "gfx.tick1.Tick1";

    private MainClass() {
    }
}
