package gfx.tick1;

import java.io.PrintWriter;
import java.time.Duration;
import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Where a run's time goes, for {@code --timings} and the benchmark's startup breakdown: from
 * the process's start to {@code main} (JVM start and class loading), then each phase in turn.
 */
final class Timings {

    /** Taken as the first thing in {@code main}. */
    private static long mainNanos = System.nanoTime();
    private static Instant mainInstant = Instant.now();

    private final Map<String, Long> phases = new LinkedHashMap<>();
    private long last = mainNanos;

    static void mainStarted() {
        mainNanos = System.nanoTime();
        mainInstant = Instant.now();
    }

    /** Ends the phase called {@code name}, which began when the previous one ended. */
    void end(String name) {
        long now = System.nanoTime();
        phases.put(name, now - last);
        last = now;
    }

    /** One line: {@code timings: jvm 61.0 ms, command line 35.2 ms, ...}. */
    void print(PrintWriter err) {
        StringBuilder line = new StringBuilder("timings:");
        ProcessHandle.current().info().startInstant().ifPresent(start -> line.append(String.format(
                " jvm start and class loading %.1f ms,", Duration.between(start, mainInstant).toNanos() / 1e6)));
        phases.forEach((name, nanos) -> line.append(String.format(" %s %.1f ms,", name, nanos / 1e6)));
        line.setLength(line.length() - 1);
        err.println(line);
    }
}
