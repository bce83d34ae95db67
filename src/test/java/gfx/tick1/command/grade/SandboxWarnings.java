package gfx.tick1.command.grade;

import java.util.ArrayList;
import java.util.List;

/**
 * A grade's standard error without the sandbox's warnings, which end it where a machine gives the sandbox less than
 * it could (no control group, the output folders on the host's disk as a normal user): the grade's own words.
 */
final class SandboxWarnings {

    private SandboxWarnings() {
    }

    /** {@code err} less the warning lines at its end (that of --no-sandbox, said before the grade, is kept). */
    static String stripped(String err) {
        List<String> lines = new ArrayList<>(err.lines().toList());
        while (!lines.isEmpty() && lines.get(lines.size() - 1).startsWith("tick1 grade: warning: ")
                && !lines.get(lines.size() - 1).contains("--no-sandbox")) {
            lines.remove(lines.size() - 1);
        }
        return lines.isEmpty() ? "" : String.join(System.lineSeparator(), lines) + System.lineSeparator();
    }
}
