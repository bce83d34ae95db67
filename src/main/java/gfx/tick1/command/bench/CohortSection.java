package gfx.tick1.command.bench;

import gfx.tick1.command.shared.kit.StarterKit;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Locale;

/**
 * The benchmark's cohort section: {@code tick1 grade --submissions} on a generated cohort of
 * correct solutions, with its defaults (as many jobs as cores, the sandbox), in a fresh process: the wall time per
 * submission and the median of the submissions' own times. The correct solution is tick1's own, in the starter's
 * package ({@link StarterKit#solution}), which the program holds: the section is measured wherever it runs.
 */
final class CohortSection {

    private CohortSection() {
    }

    /**
     * Measures a cohort of {@code count} submissions with {@code runs}, in {@code folder} (an empty folder), and
     * appends the section to {@code report}; returns what was measured, or null where nothing could be.
     */
    static CohortTiming.Measured appendTo(Path report, ProcessRuns runs, int count, Path folder, PrintWriter log)
            throws IOException {
        String section;
        CohortTiming.Measured measured = null;
        log.printf("grading a cohort of %d correct solutions%n", count);
        log.flush();
        try {
            String loadBefore = loadAverage();
            CohortTiming.Measured m = CohortTiming.measure(runs, StarterKit.solution("Sphere"),
                    StarterKit.solution("Renderer"), count, folder);
            measured = m;
            section = markdown(m) + "\nThe machine's load average (1 minute) was " + loadBefore
                    + " before the grade and " + loadAverage() + " after it: other work on the machine slows "
                    + "every submission.\n";
        } catch (IOException e) {
            section = heading() + "Not measured: " + e.getMessage() + ".\n";
        }
        Files.writeString(report, "\n" + section, StandardCharsets.UTF_8, StandardOpenOption.APPEND);
        return measured;
    }

    /** The first figure of /proc/loadavg, or "unknown" where there is none. */
    static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
    }

    private static String heading() {
        return "## Grading a cohort\n\n";
    }

    static String markdown(CohortTiming.Measured m) {
        return heading() + String.format(Locale.ROOT, """
                `tick1 grade --submissions` with its defaults, in a fresh process, on a generated Moodle download of \
                %d correct solutions (each with a comment of its own, so none is taken from another's result), %d \
                at a time (the default: the cores), in the bubblewrap sandbox, into an empty report folder. The \
                wall time covers the whole command: the JVM's start, reading the scenes and the download, the \
                class-sharing archive made once for the cohort, every submission, the reference images (rendered \
                once per scene), the look-alikes and the report. %d of %d passed.

                | measure | seconds |
                | --- | ---: |
                | wall time per submission (whole grade / submissions) | %.3f |
                | whole grade, wall | %.1f |
                | median of the submissions' times in the report (one job's view) | %.3f |

                A submission's time in the report is one job's view while the other jobs run beside it, so it is \
                more than the wall time per submission.
                """, m.submissions(), m.jobs(), m.passed(), m.submissions(), m.wallPerSubmission(), m.wallSeconds(),
                m.medianSubmissionSeconds());
    }
}
