package gfx.tick1.grade;

import gfx.tick1.cli.ExitStatuses;
import gfx.tick1.grade.cohort.CohortGrade;
import gfx.tick1.grade.cohort.ResultStore;
import gfx.tick1.grade.grading.Grading;
import gfx.tick1.grade.grading.SubmissionGrader;
import gfx.tick1.grade.intake.Submissions;
import gfx.tick1.grade.model.CohortInputException;
import gfx.tick1.grade.model.StudentResult;
import gfx.tick1.grade.model.Submission;
import gfx.tick1.grade.report.CohortOutputs;
import gfx.tick1.grade.report.CohortReport;
import gfx.tick1.grade.report.ReportFiles;
import gfx.tick1.grade.report.Worksheet;
import gfx.tick1.grade.sandbox.ChildOutput;
import gfx.tick1.grade.sandbox.Sandbox;
import gfx.tick1.grade.sandbox.WorkFolder;
import gfx.tick1.io.IoErrors;
import gfx.tick1.scene.SceneException;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZonedDateTime;
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

    /** The gradebook in the report folder, in the form of Moodle's grading worksheet. */
    static final String GRADES = "grades.csv";

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
            submissions = withoutOwnFiles(Submissions.read(options.submissions()));
            if (options.worksheet() != null && Files.isDirectory(options.worksheet())) {
                throw new IOException(options.worksheet() + ": a folder, not a worksheet (--worksheet wants the "
                        + "CSV file downloaded from the assignment)");
            }
            if (options.worksheet() != null && !Files.isRegularFile(options.worksheet())) {
                throw new java.nio.file.NoSuchFileException(options.worksheet().toString());
            }
        } catch (IOException e) {
            err.println("tick1 grade: " + IoErrors.describe(e));
            return GradeCommand.EXIT_USAGE;
        }
        if (options.scenesFolder() == null) {
            err.println("tick1 grade: the built-in hidden scene is public (it is in tick1): anyone can pass it by "
                    + "copying its images; give scenes of your own with --scenes");
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
                err.println("tick1 grade: " + IoErrors.describe(e));
                return GradeCommand.EXIT_USAGE;
            }
            try {
                store = new ResultStore(Files.createDirectories(options.reportFolder()).resolve(STATE_FOLDER));
            } catch (IOException e) {
                err.println("tick1 grade: " + options.reportFolder() + ": cannot write the report: "
                        + IoErrors.describe(e));
                return GradeCommand.EXIT_CANNOT_WRITE;
            }
            CohortGrade cohort = new CohortGrade(grading, sandbox, options.jobs(), store, err,
                    System.console() != null);
            running.set(cohort);
            CohortGrade.Done done = cohort.run(submissions, work);
            if (cohort.stopped()) {
                // Stopped part way: the report of the last whole run stays as it was.
                err.println("tick1 grade: stopped; the results finished so far are kept in "
                        + options.reportFolder().resolve(STATE_FOLDER) + ": run the same command again to grade "
                        + "the rest and write the report");
                return GradeCommand.EXIT_STOPPED;
            }
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
        List<StudentResult> results = CohortOutputs.withPlainFolders(done.results());
        try {
            CohortOutputs.placeImages(results, done.images(), report);
            // The gradebook first: the cohort's page links to it when it is there.
            writeGrades(results, report);
            CohortReport.write(report, results,
                    result -> Worksheet.grade(CohortOutputs.grade(result, options.maxGrade(), options.perScene())));
        } catch (CohortInputException e) {
            err.println("tick1 grade: " + e.getMessage());
            return GradeCommand.EXIT_USAGE;
        } catch (IOException e) {
            err.println("tick1 grade: " + report + ": cannot write the report: " + IoErrors.describe(e));
            return GradeCommand.EXIT_CANNOT_WRITE;
        }
        long passed = results.stream().filter(StudentResult::passed).count();
        // A submission with a problem (a missing file, ...) is never run, so neither now nor earlier.
        long problems = results.stream().filter(result -> result.submission().problem() != null).count();
        out.println("Graded " + SubmissionGrader.count(results.size(), "submission") + " ("
                + (results.size() - done.stored() - problems) + " now, " + done.stored() + " from earlier runs"
                + (problems > 0 ? ", " + problems + " not run: a problem with their files" : "") + "): "
                + passed + " passed, " + (results.size() - passed) + " failed.");
        out.println("Grades: " + report.resolve(GRADES) + "; report: " + report.resolve("index.html"));
        for (CohortGrade.Ungraded ungraded : done.ungraded()) {
            err.println("tick1 grade: " + printable(ungraded.folder()) + ": not graded: " + ungraded.why()
                    + (ungraded.grader() ? "" : " " + report));
        }
        return done.ungraded().isEmpty() ? GradeCommand.EXIT_PASS
                : done.ungraded().stream().anyMatch(CohortGrade.Ungraded::grader) ? ExitStatuses.EXIT_INTERNAL
                : GradeCommand.EXIT_CANNOT_WRITE;
    }

    /**
     * The submissions without the report folder and the worksheet, when they are in the download's
     * folder (a report written beside the students' folders is not a student).
     */
    private List<Submission> withoutOwnFiles(List<Submission> submissions) {
        Path download = options.submissions().toAbsolutePath().normalize();
        List<String> own = new java.util.ArrayList<>();
        for (Path path : new Path[] {options.reportFolder(), options.worksheet()}) {
            if (path != null && download.equals(path.toAbsolutePath().normalize().getParent())) {
                own.add(path.getFileName().toString());
            }
        }
        return submissions.stream().filter(submission -> !own.contains(submission.folder())).toList();
    }

    /** A name from the download as one line of plain text (a newline in a folder name included). */
    private static String printable(String text) {
        return ChildOutput.printable(text).replace('\n', '?');
    }

    /**
     * grades.csv: the worksheet given with --worksheet, its Grade and Feedback comments cells filled in
     * for the students graded (the file given is only read), or else a fresh worksheet. The students
     * of the one without submissions, and the submissions without a row, go to standard error.
     */
    private void writeGrades(List<StudentResult> results, Path report) throws IOException {
        List<Worksheet.Mark> marks = results.stream()
                .map(result -> Worksheet.Mark.of(result,
                        CohortOutputs.grade(result, options.maxGrade(), options.perScene())))
                .toList();
        if (options.worksheet() == null) {
            byte[] fresh = Worksheet.fresh(marks, options.maxGrade(), ZonedDateTime.now());
            ReportFiles.write(report.resolve(GRADES), out -> out.write(fresh));
            return;
        }
        Worksheet.Filled filled = Worksheet.fill(options.worksheet(), marks);
        ReportFiles.write(report.resolve(GRADES), out -> out.write(filled.bytes()));
        for (String student : filled.withoutSubmission()) {
            err.println("tick1 grade: " + options.worksheet() + ": " + printable(student) + " has no submission");
        }
        for (String student : filled.withoutRow()) {
            err.println("tick1 grade: " + options.worksheet() + ": no row for " + printable(student)
                    + ": graded in the report, but not in grades.csv");
        }
    }
}
