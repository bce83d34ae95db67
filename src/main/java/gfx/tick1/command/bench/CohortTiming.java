package gfx.tick1.command.bench;

import gfx.tick1.command.shared.grader.cohort.CohortGrade;
import gfx.tick1.command.shared.grader.cohort.ResultStore;
import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.grading.ReferenceChoice;
import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.model.Submission.SourceFile;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.engine.io.ProgressLine;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Times the grading of a cohort of copies of one solution, for {@code tick1 bench}: the sandbox,
 * the limits and the scenes of a default {@code tick1 grade --submissions}, at the size given.
 */
final class CohortTiming {

    /**
     * What was measured: the cohort's size, the jobs, how many passed, the wall time of the whole
     * grade (the shared set-up included), the median time per submission of each phase, and what the
     * control groups and the output folders' own file systems add to a submission, in seconds.
     */
    public record Measured(int submissions, int jobs, int passed, double wallSeconds, Medians medians,
            Overheads perSubmission) {

        /** The wall time of the whole grade shared out over the submissions. */
        public double wallPerSubmission() {
            return wallSeconds / submissions;
        }
    }

    /** The median time per submission of each phase, and of the whole of one submission, in seconds. */
    public record Medians(double compile, double render, double compare, double total) {
    }

    /**
     * What a submission's sandbox runs add beyond the grade's own work, in seconds: their control
     * groups, and their output folders' own file systems.
     */
    public record Overheads(double cgroup, double outputDisk, double systemFiles) {
    }

    /** Why the cohort could not be timed (no sandbox here). */
    public static final class Unavailable extends Exception {
        private static final long serialVersionUID = 1L;

        Unavailable(String reason) {
            super(reason);
        }
    }

    /**
     * The sandbox runs of one submission, each in a control group and with an output file system of
     * its own: tick1.xml with the probes, and the hidden scene (the job's warm compiler has one group
     * for all its compiles, and writes to the grader's disk).
     */
    public static final int RUNS_PER_SUBMISSION = 2;
    /** How many times the parts of a control group's cost, and an output file system's, are timed. */
    private static final int CGROUP_PROBES = 51;

    /** {@code tick1 grade}'s default --memory: the heap for the student's code (the compiler has at least 256 MiB). */
    private static final int DEFAULT_MEMORY_MEGABYTES = 512;

    private CohortTiming() {
    }

    /**
     * Grades {@code count} submissions, each {@code sphere} and {@code renderer} with a comment of
     * its own at the end (so that no two have the same files and none is taken from another's
     * result), {@code jobs} at a time, at {@code width} x {@code height}, in a fresh report folder.
     */
    public static Measured measure(String sphere, String renderer, int count, int jobs, int width, int height)
            throws IOException, InterruptedException, Unavailable {
        Sandbox sandbox;
        try {
            sandbox = Sandbox.confined();
        } catch (Sandbox.Unavailable e) {
            throw new Unavailable(e.getMessage());
        }
        List<Submission> submissions = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            submissions.add(new Submission("student-" + i, Integer.toString(i), "Student " + i,
                    new SourceFile("Sphere.java",
                            (sphere + "\n// student " + i + "\n").getBytes(StandardCharsets.UTF_8)),
                    new SourceFile("Renderer.java", renderer.getBytes(StandardCharsets.UTF_8)), null));
        }
        Path work = Files.createTempDirectory("tick1-grade");
        Path report = Files.createTempDirectory("tick1-bench-cohort");
        try {
            long start = System.nanoTime();
            Grading grading = Grading.prepare(Files.createDirectory(work.resolve("grading")), null,
                    new Grading.Limits(width, height, Duration.ofSeconds(60), DEFAULT_MEMORY_MEGABYTES,
                            ReferenceChoice.either));
            CohortGrade.Done done = new CohortGrade(grading, sandbox, jobs, new ResultStore(report.resolve("state")),
                    new PrintWriter(Writer.nullWriter()), new ProgressLine(new PrintWriter(Writer.nullWriter()), false,
                    Duration.ZERO, Duration.ZERO)).run(submissions, work);
            double wall = (System.nanoTime() - start) / 1e9;
            List<SubmissionGrader.Phases> phases = done.phases();
            SandboxOverheads overheads = new SandboxOverheads(sandbox);
            return new Measured(count, jobs, (int) done.results().stream().filter(r -> r.passed()).count(), wall,
                    new Medians(median(phases.stream().mapToLong(SubmissionGrader.Phases::compileNanos).toArray()),
                            median(phases.stream().mapToLong(SubmissionGrader.Phases::renderNanos).toArray()),
                            median(phases.stream().mapToLong(SubmissionGrader.Phases::compareNanos).toArray()),
                            median(done.results().stream().mapToLong(r -> r.time().toNanos()).toArray())),
                    new Overheads(RUNS_PER_SUBMISSION * overheads.cgroupSeconds(CGROUP_PROBES),
                            RUNS_PER_SUBMISSION * overheads.outputDiskSeconds(CGROUP_PROBES),
                            RUNS_PER_SUBMISSION * overheads.systemFilesSeconds(CGROUP_PROBES)));
        } finally {
            WorkFolder.delete(work);
            WorkFolder.delete(report);
        }
    }

    /** The median of {@code nanos}, in seconds; NaN for none. */
    static double median(long[] nanos) {
        if (nanos.length == 0) {
            return Double.NaN;
        }
        long[] sorted = nanos.clone();
        Arrays.sort(sorted);
        int middle = sorted.length / 2;
        return (sorted.length % 2 == 1 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2.0) / 1e9;
    }
}
