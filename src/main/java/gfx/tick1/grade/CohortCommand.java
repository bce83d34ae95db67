package gfx.tick1.grade;

import gfx.tick1.grade.cohort.StudentResult;
import gfx.tick1.grade.cohort.Submission;
import gfx.tick1.scene.SceneException;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

/**
 * {@code tick1 grade --submissions}: reads the cohort's download, grades every submission
 * ({@link CohortGrade}), and writes grades.csv, the feedback folders and index.html from every
 * result, those of earlier runs included.
 */
final class CohortCommand {

    /** The folder inside the report folder where each result is kept as soon as it is known. */
    static final String STATE_FOLDER = "state";

    private final GradeCommand options;
    private final Sandbox sandbox;
    private final PrintWriter out;
    private final PrintWriter err;

    CohortCommand(GradeCommand options, Sandbox sandbox, PrintWriter out, PrintWriter err) {
        this.options = options;
        this.sandbox = sandbox;
        this.out = out;
        this.err = err;
    }

    int call() throws IOException, InterruptedException {
        List<Submission> submissions;
        try {
            submissions = CohortIntake.read(options.submissions());
            if (options.worksheet() != null && !Files.isRegularFile(options.worksheet())) {
                throw new java.nio.file.NoSuchFileException(options.worksheet().toString());
            }
        } catch (IOException e) {
            err.println("tick1 grade: " + GradeCommand.describe(e));
            return GradeCommand.EXIT_USAGE;
        }
        Path work = Files.createTempDirectory("tick1-grade");
        AtomicReference<CohortGrade> running = new AtomicReference<>();
        // Ctrl-C or SIGTERM: stop the students' processes and delete the work folder. Finished
        // results are in the store already; the one being stored is renamed into place whole or
        // not at all.
        Thread cleanUp = new Thread(() -> {
            CohortGrade cohort = running.get();
            if (cohort != null) {
                cohort.stop();
            }
            GradeCommand.reportUndeleted(WorkFolder.delete(work), err);
        });
        Runtime.getRuntime().addShutdownHook(cleanUp);
        try {
            Grading grading;
            ResultStore store;
            try {
                sandbox.checkReachable(work);
                grading = Grading.prepare(Files.createDirectory(work.resolve("grading")), options.scenesFolder(),
                        options.limits());
            } catch (SceneException e) {
                err.println("tick1 grade: " + e.getMessage());
                return GradeCommand.EXIT_USAGE;
            } catch (IOException e) {
                err.println("tick1 grade: " + GradeCommand.describe(e));
                return GradeCommand.EXIT_USAGE;
            }
            try {
                store = new ResultStore(Files.createDirectories(options.reportFolder()).resolve(STATE_FOLDER));
            } catch (IOException e) {
                err.println("tick1 grade: " + options.reportFolder() + ": cannot write the report: "
                        + GradeCommand.describe(e));
                return GradeCommand.EXIT_CANNOT_WRITE;
            }
            CohortGrade cohort = new CohortGrade(grading, sandbox, options.jobs(), store, err,
                    System.console() != null);
            running.set(cohort);
            CohortGrade.Done done = cohort.run(submissions, work);
            return report(done);
        } finally {
            CohortGrade cohort = running.getAndSet(null);
            if (cohort != null) {
                cohort.stop();
            }
            GradeCommand.reportUndeleted(WorkFolder.delete(work), err);
            try {
                Runtime.getRuntime().removeShutdownHook(cleanUp);
            } catch (IllegalStateException e) {
                // The JVM is shutting down: the hook runs (or ran) anyway.
            }
        }
    }

    /** Writes grades.csv, the feedback folders and index.html from every result, and says what was done. */
    private int report(CohortGrade.Done done) {
        Path report = options.reportFolder();
        List<StudentResult> results = done.results();
        try {
            CohortOutputs.placeImages(results, done.images(), report);
            // The gradebook, the feedback pages and the cohort's page, from every result.
            CohortOutputs.writeFeedback(results, report);
            CohortOutputs.writeGrades(results, report, options.maxGrade(), options.perScene());
            CohortOutputs.writeIndex(results, report);
        } catch (IOException e) {
            err.println("tick1 grade: " + report + ": cannot write the report: " + GradeCommand.describe(e));
            return GradeCommand.EXIT_CANNOT_WRITE;
        }
        long passed = results.stream().filter(StudentResult::passed).count();
        out.println("Graded " + SubmissionGrader.count(results.size(), "submission") + " ("
                + (results.size() - done.stored() - done.ungraded().size()) + " now, " + done.stored()
                + " from earlier runs): " + passed + " passed, " + (results.size() - passed) + " failed.");
        out.println("Grades: " + report.resolve("grades.csv") + "; report: " + report.resolve("index.html"));
        for (String folder : done.ungraded()) {
            err.println("tick1 grade: " + folder + ": not graded: its images could not be stored in " + report);
        }
        return done.ungraded().isEmpty() ? GradeCommand.EXIT_PASS : GradeCommand.EXIT_CANNOT_WRITE;
    }
}
