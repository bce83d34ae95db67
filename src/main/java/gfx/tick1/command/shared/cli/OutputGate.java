package gfx.tick1.command.shared.cli;

import java.io.PrintWriter;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;

/**
 * A command's outputs, which a stop shuts. Stopped (Ctrl-C, SIGTERM), Java ends when its shutdown hooks do,
 * whatever the command's threads are doing meanwhile: what they print after the hook has said that the command
 * stopped (a verdict on a run that the stop itself ended, an error from a work folder the hook deleted) would
 * contradict that line. Once {@link #shutSaying shut}, the writers this gate {@link #wrap}ped drop what they are given.
 */
public final class OutputGate {

    private final Object lock = new Object();
    /** The standard error itself, past the gate: for the line that says the command stopped, and what follows it. */
    private final PrintWriter past;
    private final List<PrintWriter> targets = new ArrayList<>();
    private boolean shut;

    /** A gate whose stop line goes to {@code err}, the command's standard error. */
    public OutputGate(PrintWriter err) {
        this.past = err;
    }

    /** A writer that prints to {@code target} until the gate is shut, then drops everything. */
    public PrintWriter wrap(PrintWriter target) {
        synchronized (lock) {
            targets.add(target);
        }
        return new PrintWriter(new Writer() {
            @Override
            public void write(char[] text, int offset, int length) {
                synchronized (lock) {
                    if (!shut) {
                        target.write(text, offset, length);
                    }
                }
            }

            @Override
            public void flush() {
                synchronized (lock) {
                    if (!shut) {
                        target.flush();
                    }
                }
            }

            @Override
            public void close() {
                flush();
            }
        });
    }

    /**
     * Shuts the gate and prints {@code line} past it: nothing printed through the gate comes after that line. What
     * passed before is flushed first. Once shut, the gate says nothing more.
     */
    public void shutSaying(String line) {
        synchronized (lock) {
            if (shut) {
                return;
            }
            shut = true;
            targets.forEach(PrintWriter::flush);
        }
        past.println(line);
        past.flush();
    }

    /** The standard error past the gate, for what a stop has to say after its line (what it could not delete). */
    public PrintWriter past() {
        return past;
    }
}
