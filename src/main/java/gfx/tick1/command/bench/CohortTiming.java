package gfx.tick1.command.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Times the grading of a cohort of copies of one solution, for {@code tick1 bench}, as an organiser grades one:
 * {@code tick1 grade --submissions} with its defaults on a generated Moodle download, in a fresh process. What it
 * reports comes from what that command prints and writes: how many passed from its last line, each submission's
 * time from its index.html.
 */
final class CohortTiming {

    /**
     * What was measured: the cohort's size, the jobs, how many passed, the wall time of the whole grade (the JVM's
     * start and the shared set-up included), and the median of the submissions' times as the report gives them (one
     * job's view, while the other jobs run beside it), in seconds.
     */
    record Measured(int submissions, int jobs, int passed, double wallSeconds, double medianSubmissionSeconds) {

        /** The wall time of the whole grade shared out over the submissions. */
        double wallPerSubmission() {
            return wallSeconds / submissions;
        }
    }

    /** The count of passes in the grade's last line: "Graded 100 submissions (100 now, 0 ...): 100 passed, ...". */
    private static final Pattern PASSED = Pattern.compile("Graded \\d+ submissions? \\([^)]*\\): (\\d+) passed");
    /** A submission's time in the report's table, in milliseconds: the cell its column sorts by. */
    private static final Pattern TIME = Pattern.compile("<td class=\"time\" data-sort=\"(\\d+)\">");

    private CohortTiming() {
    }

    /**
     * Grades {@code count} submissions, each {@code sphere} and {@code renderer} with a comment of its own at the end
     * (so that no two have the same files and none is taken from another's result), in {@code folder}, an empty
     * folder for the download and the report.
     *
     * @throws IOException with the grade's first line on standard error where it could not grade (no sandbox)
     */
    static Measured measure(ProcessRuns runs, String sphere, String renderer, int count, Path folder)
            throws IOException {
        Path download = Files.createDirectory(folder.resolve("download"));
        for (int i = 0; i < count; i++) {
            // Moodle's folder for a file submission: the full name, the participant's id, the plugin.
            int id = 1001 + i;
            Path student = Files.createDirectory(download.resolve("Student " + i + "_" + id
                    + "_assignsubmission_file_"));
            Files.writeString(student.resolve("Sphere.java"), sphere + "\n// student " + i + "\n",
                    StandardCharsets.UTF_8);
            Files.writeString(student.resolve("Renderer.java"), renderer, StandardCharsets.UTF_8);
        }
        Path report = folder.resolve("report");
        ProcessRuns.Ran ran = runs.once(0, "grade", "--submissions", download.toString(), "--report",
                report.toString());
        Matcher passed = PASSED.matcher(ran.out());
        if (!passed.find()) {
            throw new IOException("tick1 grade --submissions did not say how many passed: "
                    + ran.out().strip().lines().reduce((first, last) -> last).orElse("(it printed nothing)"));
        }
        Matcher time = TIME.matcher(Files.readString(report.resolve("index.html"), StandardCharsets.UTF_8));
        long[] millis = time.results().mapToLong(result -> Long.parseLong(result.group(1))).toArray();
        return new Measured(count, Runtime.getRuntime().availableProcessors(), Integer.parseInt(passed.group(1)),
                ran.millis() / 1e3, median(millis) / 1e3);
    }

    /** The median of {@code values}; NaN for none. */
    static double median(long[] values) {
        if (values.length == 0) {
            return Double.NaN;
        }
        long[] sorted = values.clone();
        Arrays.sort(sorted);
        int middle = sorted.length / 2;
        return sorted.length % 2 == 1 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2.0;
    }
}
