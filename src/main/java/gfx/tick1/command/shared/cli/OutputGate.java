package gfx.tick1.command.shared.cli;

import java.io.PrintWriter;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;

/**
 * A command's outputs, which a stop shuts. Stopped (Ctrl-C, SIGTERM), Java ends when its shutdown hooks do,
 * whatever the command's threads are doing meanwhile: what they print after the hook has said that the command
 * stopped (a verdict on a run that the stop itself ended, an error from a work folder the hook deleted) would
 * contradict that line. Once {@link #shut()}, the writers this gate {@link #wrap}ped drop what they are given.
 */
public final class OutputGate {

    private final Object lock = new Object();
    private final List<PrintWriter> targets = new ArrayList<>();
    private boolean shut;

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
     * Shuts the gate: once this returns, nothing more passes through it, and what passed is flushed. Whatever the
     * caller prints next on the targets themselves comes last.
     */
    public void shut() {
        synchronized (lock) {
            shut = true;
            targets.forEach(PrintWriter::flush);
        }
    }
}
