package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.TimeUnit;

/** The grader's own short commands (chmod, rm, mount, umount), run to their end whatever happens meanwhile. */
final class Commands {

    private Commands() {
    }

    /**
     * Runs {@code command} to its end, at most two minutes, whatever this thread's interrupt status
     * (the grade may be stopping: what it cleans must still go); whether it exited 0.
     */
    static boolean run(List<String> command) {
        Process process;
        try {
            process = new ProcessBuilder(command).redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        } catch (IOException e) {
            return false;   // no such program here
        }
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(2);
        boolean interrupted = false;
        try {
            while (true) {
                try {
                    if (process.waitFor(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS)) {
                        return process.exitValue() == 0;
                    }
                    process.destroyForcibly();
                    return false;
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
