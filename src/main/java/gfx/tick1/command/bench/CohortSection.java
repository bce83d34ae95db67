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
 * correct solutions, with the default jobs, in the sandbox: the wall time per submission and the
 * median time of each phase. The correct solution is tick1's own, in the starter's package
 * ({@link StarterKit#solution}), which the program holds: the section is measured wherever it runs.
 */
final class CohortSection {

    /** The course grades at 640 x 480. */
    private static final int WIDTH = 640, HEIGHT = 480;

    private CohortSection() {
    }

    /**
     * Measures a cohort of {@code count} submissions and appends the section to {@code report}; returns what was
     * measured, or null where nothing could be.
     */
    static CohortTiming.Measured appendTo(Path report, int count, PrintWriter log) throws IOException {
        int jobs = Runtime.getRuntime().availableProcessors();
        String section;
        CohortTiming.Measured measured = null;
        log.printf("grading a cohort of %d correct solutions, %d at a time%n", count, jobs);
        log.flush();
        try {
            String loadBefore = loadAverage();
            CohortTiming.Measured m = CohortTiming.measure(StarterKit.solution("Sphere"),
                    StarterKit.solution("Renderer"), count, jobs, WIDTH, HEIGHT);
            measured = m;
            section = markdown(m) + "\nThe machine's load average (1 minute) was " + loadBefore
                    + " before the grade and " + loadAverage() + " after it: other work on the machine slows "
                    + "every phase.\n";
        } catch (CohortTiming.Unavailable e) {
            section = heading() + "Not measured: " + e.getMessage() + ".\n";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            section = heading() + "Not measured: interrupted.\n";
        }
        Files.writeString(report, "\n" + section, StandardCharsets.UTF_8, StandardOpenOption.APPEND);
        return measured;
    }

    /** The first figure of /proc/loadavg, or "unknown" where there is none. */
    private static String loadAverage() {
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
                `tick1 grade --submissions` on a generated cohort of %d correct solutions (each with a comment of \
                its own, so none is taken from another's result), %d at a time (the default: the cores), at \
                %d x %d, in the bubblewrap sandbox, into an empty report folder. The wall time covers the whole \
                grade: reading the scenes, the class-sharing archive made once for the cohort, every submission, \
                the reference images (rendered once per scene). %d of %d passed.

                | measure | seconds |
                | --- | ---: |
                | wall time per submission (whole grade / submissions) | %.3f |
                | whole grade, wall | %.1f |
                | median per submission: compile (by the job's warm compiler, in the sandbox) | %.3f |
                | median per submission: render (tick1.xml with the probes, then the hidden scene) | %.3f |
                | median per submission: compare (with the references, explanations and images of failures) | %.3f |
                | median per submission: total, one job's view | %.3f |
                | per submission: the control groups (%d runs, each making, joining, removing one) | %.4f |
                | per submission: the output folders' file systems (%d runs, each mounting, counting, \
                unmounting one) | %.4f |
                | per submission: the JDK's files and libraries, each bound on its own and read into memory before \
                the run (%d runs) | %.4f |

                The phases are the grader's view of one submission while the other jobs run beside it, so they \
                add up to more than the wall time per submission.
                """, m.submissions(), m.jobs(), WIDTH, HEIGHT, m.passed(), m.submissions(), m.wallPerSubmission(),
                m.wallSeconds(), m.medians().compile(), m.medians().render(), m.medians().compare(),
                m.medians().total(), CohortTiming.RUNS_PER_SUBMISSION, m.perSubmission().cgroup(),
                CohortTiming.RUNS_PER_SUBMISSION, m.perSubmission().outputDisk(),
                CohortTiming.RUNS_PER_SUBMISSION, m.perSubmission().systemFiles());
    }
}
