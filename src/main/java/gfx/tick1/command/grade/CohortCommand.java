package gfx.tick1.command.grade;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.OutputGate;
import gfx.tick1.command.shared.grader.cohort.CohortGrade;
import gfx.tick1.command.shared.grader.cohort.Ungraded;
import gfx.tick1.command.shared.grader.cohort.ResultStore;
import gfx.tick1.command.shared.grader.cohort.StoredCode;
import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.intake.Submissions;
import gfx.tick1.command.shared.grader.lookalike.Lookalikes;
import gfx.tick1.command.shared.grader.model.CohortInputException;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.report.CohortOutputs;
import gfx.tick1.command.shared.grader.report.CohortReport;
import gfx.tick1.command.shared.grader.report.ReportFiles;
import gfx.tick1.command.shared.grader.report.Worksheet;
import gfx.tick1.command.shared.grader.sandbox.ChildOutput;
import gfx.tick1.command.shared.grader.sandbox.Leftovers;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.io.Counted;
import gfx.tick1.engine.io.ProgressLine;
import gfx.tick1.engine.scene.SceneException;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;

/**
 * {@code tick1 grade --submissions}: reads the cohort's download, grades every submission
 * ({@link CohortGrade}), and writes grades.csv, the feedback folders and index.html from every
 * result, those of earlier runs included. {@link GradeCommand} parses the command line and hands
 * it the options as values: those of every grade, and the cohort's own.
 */
final class CohortCommand {

    /** The folder inside the report folder where each result is kept as soon as it is known. */
    static final String STATE_FOLDER = "state";
    /** How long a stop waits for the grades it cut short to end and delete what they began to store. */
    private static final Duration STOP_WAIT = Duration.ofMinutes(1);

    private final GradeOptions options;
    private final CohortOptions cohortOptions;
    /** The sandbox, made once the stop line is ready ({@link #call}). */
    private Sandbox sandbox;
    private final PrintWriter out;
    private final PrintWriter err;
    private final OutputGate gate;
    private final GradeStop stop;
    /** The worksheet given, read and checked before anything is graded; null without --worksheet. */
    private Worksheet worksheet;
    /** The grade of a pass: --max-grade, else the worksheet's Maximum Grade, else 1. */
    private double maxGrade;
    /** How many submissions the download holds, once read. */
    private volatile int submissionCount;

    /** The grader's own work folder, once made: a stop deletes it. */
    private volatile Path work;
    CohortCommand(GradeOptions options, CohortOptions cohortOptions, PrintWriter out, PrintWriter err,
            GradeStop stop) {
        this.options = options;
        this.cohortOptions = cohortOptions;
        this.out = out;
        this.err = err;
        this.stop = stop;
        this.gate = stop.gate();
    }

    /** Where the cohort's sandbox comes from: made when the grade asks for it. */
    @FunctionalInterface
    interface Sandboxes {
        Sandbox make() throws IOException, InterruptedException;
    }

    /**
     * Makes the sandbox, reads the download, grades and writes the report. A stop (Ctrl-C, SIGTERM) stops the jobs,
     * says how many results are kept and deletes the work folder: Java ends when its hooks do.
     */
    int call(Sandboxes sandboxes) throws IOException, InterruptedException {
        AtomicReference<CohortGrade> running = new AtomicReference<>();
        stop.onStop(() -> {
            CohortGrade cohort = stopJobs(running);
            gate.shutSaying(StopLine.of(options.reportFolder().resolve(STATE_FOLDER),
                    cohort == null ? 0 : cohort.kept(), cohort == null ? 0 : submissionCount));
            deleteWork(gate.past());
        });
        try {
            sandbox = sandboxes.make();
            return call(running);
        } finally {
            stop.end(() -> {
                stopJobs(running);
                deleteWork(err);
            });
        }
    }

    private int call(AtomicReference<CohortGrade> running) throws IOException, InterruptedException {
        refuseReportInTheDownload();
        List<Submission> submissions;
        try {
            // The worksheet first: a bad one must stop the grade before anything is graded or written.
            readWorksheet();
            submissions = withoutOwnFiles(Submissions.read(cohortOptions.submissions()));
        } catch (IOException e) {
            throw new CommandFailure(GradeCommand.EXIT_USAGE, IoErrors.describe(e));
        }
        if (submissions.isEmpty()) {
            // Only the report folder or the worksheet was there: a grades.csv of no one is no grade.
            throw new CommandFailure(GradeCommand.EXIT_USAGE, cohortOptions.submissions() + ": no submissions: it "
                    + "holds only the report folder or the worksheet");
        }
        submissionCount = submissions.size();
        if (options.scenesFolder() == null) {
            err.println("tick1 grade: the built-in hidden scene is public (it is in tick1): anyone can pass it by "
                    + "copying its images; give scenes of your own with --scenes");
        }
        for (Submission submission : submissions) {
            if (!Submissions.namedByMoodle(submission)) {
                err.println("tick1 grade: " + printable(submission.folder()) + ": not a name Moodle gives a "
                        + "student's folder or file (Full Name_<participant id>_assignsubmission_file): graded in "
                        + "the report, but given no row in grades.csv");
            }
        }
        Submissions.sharedIds(submissions).forEach((id, folders) -> err.println("tick1 grade: participant "
                + printable(id) + " has " + folders.size() + " folders in the download (" + printable(String.join(
                        ", ", folders.subList(0, Math.min(3, folders.size())))) + (folders.size() > 3 ? ", ..." : "")
                + "): each fails ungraded until one is left"));
        // What killed runs left (mounts, control groups, work folders that may hold hidden scenes) goes first.
        GradeCommand.reportUndeleted(Leftovers.remove(), err);
        work = Leftovers.newWorkFolder("grade");
        return gradeAndReport(submissions, work, running);
    }

    /**
     * Reads and checks --worksheet, and settles the grade of a pass: a --max-grade that differs from
     * the worksheet's Maximum Grade is refused, since Moodle would take its grades on the wrong scale.
     */
    private void readWorksheet() throws CohortInputException {
        Double given = cohortOptions.maxGrade();
        Double sheet = null;
        if (cohortOptions.worksheet() != null) {
            worksheet = Worksheet.read(cohortOptions.worksheet());
            sheet = worksheet.maximumGrade();
        }
        if (given != null && sheet != null && Math.abs(given - sheet) > 1e-9) {
            throw new CohortInputException("--max-grade " + Worksheet.grade(given) + " differs from the Maximum Grade "
                    + Worksheet.grade(sheet) + " of " + cohortOptions.worksheet() + ": leave --max-grade out to grade "
                    + "out of " + Worksheet.grade(sheet) + ", or change the assignment's maximum in Moodle first");
        }
        maxGrade = given != null ? given : sheet != null ? sheet : 1;
    }

    /**
     * Stops the grade, if it runs, and waits for every job's grade to end (what a grade cut short began to store is
     * then deleted); the grade stopped, or null.
     */
    private static CohortGrade stopJobs(AtomicReference<CohortGrade> running) {
        CohortGrade cohort = running.getAndSet(null);
        if (cohort != null) {
            cohort.stop();
            try {
                cohort.awaitEnd(STOP_WAIT);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        return cohort;
    }

    /** Deletes the work folder, if made, saying on {@code to} what could not be deleted. */
    private void deleteWork(PrintWriter to) {
        if (work != null) {
            GradeCommand.reportUndeleted(WorkFolder.delete(work), to);
        }
    }

    /** Prepares the grading and the store, grades every submission, and writes the report. */
    private int gradeAndReport(List<Submission> submissions, Path work, AtomicReference<CohortGrade> running)
            throws IOException, InterruptedException {
        Grading grading;
        ResultStore store;
        try {
            sandbox.checkReachable(work);
            grading = Grading.prepare(Files.createDirectory(work.resolve("grading")), options.scenesFolder(),
                    options.limits());
        } catch (SceneException e) {
            throw new CommandFailure(GradeCommand.EXIT_USAGE, e.getMessage());
        } catch (IOException e) {
            throw new CommandFailure(GradeCommand.EXIT_USAGE, IoErrors.describe(e));
        }
        try {
            store = new ResultStore(Files.createDirectories(options.reportFolder()).resolve(STATE_FOLDER));
        } catch (IOException e) {
            throw new CommandFailure(GradeCommand.EXIT_CANNOT_WRITE, options.reportFolder()
                    + ": cannot write the report: " + IoErrors.describe(e));
        }
        CohortGrade cohort = new CohortGrade(grading, sandbox, cohortOptions.jobs(), store, err,
                new ProgressLine(err, System.console() != null, Duration.ZERO, Duration.ZERO));
        running.set(cohort);
        CohortGrade.Done done = cohort.run(submissions, work);
        if (cohort.stopped()) {
            // Stopped part way (the shutdown hook says so): the report of the last whole run stays as it was.
            return GradeCommand.EXIT_STOPPED;
        }
        return report(done);
    }

    /** Writes grades.csv, the feedback folders and index.html from every result, and says what was done. */
    private int report(CohortGrade.Done done) throws InterruptedException {
        Path report = options.reportFolder();
        List<StudentResult> results = CohortOutputs.forReport(done.results());
        // A student whose feedback cannot be written is theirs alone: once, with the first reason.
        Map<String, String> unwritten = new LinkedHashMap<>();
        try {
            CohortOutputs.placeImages(results, done.images(), report)
                    .forEach(student -> unwritten.putIfAbsent(student.folder(), student.why()));
            // The gradebook first: the cohort's page links to it when it is there.
            writeGrades(results, done.results().stream().map(StudentResult::submission)
                    .map(Submissions::namedByMoodle).toList(), report);
            CohortReport.write(report, results,
                    result -> Worksheet.grade(cohortOptions.marking().grade(result, maxGrade)),
                    cohortOptions.lookalikes()
                            ? Lookalikes.find(results, StoredCode.in(report.resolve(STATE_FOLDER))) : null)
                    .forEach(student -> unwritten.putIfAbsent(student.folder(), student.why()));
        } catch (CohortInputException e) {
            throw new CommandFailure(GradeCommand.EXIT_USAGE, e.getMessage());
        } catch (IOException e) {
            throw new CommandFailure(GradeCommand.EXIT_CANNOT_WRITE, report + ": cannot write the report: "
                    + IoErrors.describe(e));
        }
        out.println(CohortEnding.of(results, done.stored()).line());
        out.println("Grades: " + report.resolve(ReportFiles.GRADES) + "; feedback: "
                + report.resolve(ReportFiles.FEEDBACK_ZIP) + "; report: " + report.resolve("index.html"));
        done.ungraded().stream().filter(Ungraded::grader).forEach(ungraded -> err.println("tick1 grade: "
                + printable(ungraded.folder()) + ": not graded: " + ungraded.why()));
        // The report folder's fault is one, whoever met it first: said once, with that one's cause.
        List<Ungraded> unstored = done.ungraded().stream().filter(ungraded -> !ungraded.grader()).toList();
        if (!unstored.isEmpty()) {
            err.println("tick1 grade: " + report + ": cannot store results there (" + unstored.get(0).why() + "): "
                    + Counted.of(unstored.size(), "submission") + " not graded; the same command grades them once it "
                    + "can");
        }
        unwritten.forEach((folder, why) -> err.println("tick1 grade: " + printable(folder) + ": its feedback "
                + "cannot be written in " + report + " (" + why + "): its grade is in grades.csv, but its feedback "
                + "is not in feedback.zip"));
        return CohortEnding.status(done.ungraded(), unwritten.keySet());
    }

    /**
     * The submissions without the report folder and the worksheet, when they are in the download's
     * folder (a report written beside the students' folders is not a student).
     */
    private List<Submission> withoutOwnFiles(List<Submission> submissions) {
        Path download = cohortOptions.submissions().toAbsolutePath().normalize();
        List<String> own = new ArrayList<>();
        for (Path path : new Path[] {options.reportFolder(), cohortOptions.worksheet()}) {
            if (path != null && download.equals(path.toAbsolutePath().normalize().getParent())) {
                own.add(path.getFileName().toString());
            }
        }
        return submissions.stream().filter(submission -> !own.contains(submission.folder())).toList();
    }

    /**
     * Refuses a report folder that is the download, or inside a student's folder of it: the next grade would read
     * the report's files as students'. One beside the students' folders is the report's own, and left out.
     */
    private void refuseReportInTheDownload() {
        Path download = asOnDisk(cohortOptions.submissions());
        Path report = asOnDisk(options.reportFolder());
        if (report.startsWith(download) && !download.equals(report.getParent())) {
            throw new CommandFailure(GradeCommand.EXIT_USAGE, "--report " + options.reportFolder() + " is "
                    + (report.equals(download) ? "the download itself" : "inside a student's folder of the download")
                    + ": the next grade would take the report's files for students'; give a folder outside "
                    + cohortOptions.submissions());
        }
    }

    /** {@code path} absolute, with the links of the part of it that exists resolved. */
    private static Path asOnDisk(Path path) {
        Path absolute = path.toAbsolutePath().normalize();
        for (Path there = absolute; there != null; there = there.getParent()) {
            try {
                return there.toRealPath().resolve(there.relativize(absolute));
            } catch (IOException e) {
                // not there yet: try the folder that would hold it
            }
        }
        return absolute;
    }

    /** The grades.csv an earlier run wrote in {@code report}, or null: its unchanged rows keep their grading time. */
    private static byte[] earlierGrades(Path report) {
        try {
            return Files.readAllBytes(report.resolve(ReportFiles.GRADES));
        } catch (IOException e) {
            return null;
        }
    }

    /** A name from the download as one line of plain text (a newline in a folder name included). */
    private static String printable(String text) {
        return ChildOutput.printable(text).replace('\n', '?');
    }

    /**
     * grades.csv: the worksheet given with --worksheet, its Grade and Feedback comments cells filled in
     * for the students graded (the file given is only read), or else a fresh worksheet. The students
     * of the one without submissions, and the submissions without a row, go to standard error. Only a submission
     * Moodle named ({@code moodleNamed}, in the results' order) has a participant's row: any other is said so on
     * standard error when the download is read.
     */
    private void writeGrades(List<StudentResult> results, List<Boolean> moodleNamed, Path report)
            throws IOException {
        List<Worksheet.Mark> marks = new ArrayList<>();
        for (int i = 0; i < results.size(); i++) {
            if (moodleNamed.get(i)) {
                marks.add(Worksheet.Mark.of(results.get(i),
                        cohortOptions.marking().grade(results.get(i), maxGrade)));
            }
        }
        if (worksheet == null) {
            byte[] fresh = Worksheet.fresh(marks, maxGrade, ZonedDateTime.now(), earlierGrades(report));
            ReportFiles.write(report.resolve(ReportFiles.GRADES), out -> out.write(fresh));
            return;
        }
        Worksheet.Filled filled = worksheet.fill(marks);
        ReportFiles.write(report.resolve(ReportFiles.GRADES), out -> out.write(filled.bytes()));
        for (String student : filled.withoutSubmission()) {
            err.println("tick1 grade: " + cohortOptions.worksheet() + ": " + printable(student) + " has no submission");
        }
        for (String student : filled.withoutRow()) {
            err.println("tick1 grade: " + cohortOptions.worksheet() + ": no row for " + printable(student)
                    + ": graded in the report, but not in grades.csv");
        }
    }
}
