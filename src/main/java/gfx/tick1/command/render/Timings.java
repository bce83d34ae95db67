package gfx.tick1.command.render;

import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Where a run's time goes, for {@code --timings} and the benchmark's start-up breakdown: from
 * the JVM's start to {@code main}, then each phase in turn. (The JVM's uptime is read only when
 * printing, so that loading the management classes is not counted in any phase.)
 */
public final class Timings {

    /** Taken as the first thing in {@code main}. */
    private static long mainNanos = System.nanoTime();

    private final Map<String, Long> phases = new LinkedHashMap<>();
    private long last = mainNanos;

    public static void mainStarted() {
        mainNanos = System.nanoTime();
    }

    /** Ends the phase called {@code name}, which began when the previous one ended. */
    void end(String name) {
        long now = System.nanoTime();
        phases.put(name, now - last);
        last = now;
    }

    /**
     * One line: {@code timings: jvm 61.0 ms, command line 35.2 ms, ...}, then {@code more} after a
     * semicolon.
     */
    void print(PrintWriter err, String more) {
        StringBuilder line = new StringBuilder("timings:");
        double sinceMain = (System.nanoTime() - mainNanos) / 1e6;
        double uptime = ManagementFactory.getRuntimeMXBean().getUptime();
        line.append(String.format(" jvm start to main %.1f ms,", uptime - sinceMain));
        phases.forEach((name, nanos) -> line.append(String.format(" %s %.1f ms,", name, nanos / 1e6)));
        line.setLength(line.length() - 1);
        err.println(line + "; " + more);
    }
}
