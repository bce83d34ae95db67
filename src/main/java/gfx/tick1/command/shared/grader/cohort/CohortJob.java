package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.engine.io.IoErrors;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * One job: a folder, a sandbox user and a process of its own, made when it first grades, with
 * a warm compiler that compiles every submission the job grades.
 */
final class CohortJob {

    /**
     * From how many submissions to grade a class data sharing archive is made: it takes about as
     * long as grading one, and saves every scene's JVM and every warm compiler's start some of its
     * processor time (docs/benchmark.md, "What the sandbox costs").
     */
    private static final int ARCHIVE_PAYS_FROM = 8;

    /** Where a job's finished grades go: the cohort's run, which stores them. */
    interface Results {
        /** Stores the {@code index}-th submission's grade, whose images are in {@code entry}. */
        void storeResult(int index, SubmissionGrader.Graded graded, Path entry) throws IOException;
    }

    private final CohortGrade cohort;
    private final int number;
    private final Path folder;
    private final StudentProcess shared;
    private SubmissionGrader grader;

    CohortJob(CohortGrade cohort, int number, Path folder, StudentProcess shared) {
        this.cohort = cohort;
        this.number = number;
        this.folder = folder;
        this.shared = shared;
    }

    /**
     * The job's folder, sandbox and process, made when it first grades; what a failed set-up
     * made is removed, so that the job's next grade sets up afresh.
     */
    private void setUp() throws IOException {
        // Beside the job's folder, not in it: the compiler's user may not enter the job's.
        Path compilerFolder = folder.resolveSibling(folder.getFileName() + "-compiler");
        try {
            Sandbox jobSandbox = cohort.sandbox.forJob(number);
            Files.createDirectory(folder);
            cohort.grading.copyScenes(folder);
            jobSandbox.share(folder);
            StudentProcess process = shared.in(jobSandbox).withWarmCompiler(compilerFolder);
            cohort.started(process);
            grader = new SubmissionGrader(cohort.grading, jobSandbox, process, folder);
        } catch (IOException | RuntimeException e) {
            WorkFolder.delete(folder);
            WorkFolder.delete(compilerFolder);
            throw e;
        }
    }

    /**
     * Grades {@code submission}, the {@code index}-th, start to finish, and stores its result. The
     * result, or null when stop() cut the grade short (nothing is then stored).
     */
    StudentResult grade(Submission submission, int index, Results run) throws IOException, InterruptedException {
        if (grader == null) {
            setUp();
        }
        Path entry;
        try {
            entry = cohort.store.newEntry();
        } catch (IOException e) {
            throw new ReportUnwritable(IoErrors.reason(e));
        }
        Path submissionWork = null;
        try {
            submissionWork = Files.createDirectory(folder.resolve("submission-" + index));
            // What the grade says is for one student's own grade: a cohort's (its images not stored) says the cohort.
            PrintWriter quiet = new PrintWriter(Writer.nullWriter());
            SubmissionGrader.Graded graded = grader.grade(submission, submissionWork, entry, quiet, quiet);
            // A failure on a disk full without the run's own files may be the disk's: see GraderDisk.
            String diskShort = graded.result().passed() ? null : GraderDisk.shortOfSpaceBeyond(folder, submissionWork);
            if (diskShort != null) {
                throw new GraderShort(diskShort);
            }
            return stored(graded, index, entry, run);
        } finally {
            // Stored, the entry has been renamed to its key; otherwise (an error, a stop) it goes.
            WorkFolder.delete(entry);
            if (submissionWork != null) {
                WorkFolder.delete(submissionWork);
            }
        }
    }

    /** Stores a grade's result in {@code entry}; null, with nothing stored, when stop() cut it short. */
    private StudentResult stored(SubmissionGrader.Graded graded, int index, Path entry, Results run)
            throws IOException {
        // A grade cut short by stop() ended after stopping was set: it is never stored.
        if (cohort.stopped()) {
            WorkFolder.delete(entry);
            return null;
        }
        run.storeResult(index, graded, entry);
        return graded.result();
    }

    /**
     * The harness every job runs, in {@code work}: one jar, and, when there are enough submissions
     * for it to pay, a class data sharing archive made for it. Both hold only this program's and the
     * JDK's classes, so every job's user may read them.
     */
    static StudentProcess harness(CohortGrade cohort, Path work, int submissions)
            throws IOException, InterruptedException {
        Path harness = Files.createDirectory(work.resolve("harness"));
        StudentProcess.writeHarness(harness);
        WorkFolder.readableByAll(harness);
        StudentProcess process = new StudentProcess(cohort.sandbox.forJob(0), harness,
                cohort.grading.limits().memoryMegabytes());
        if (submissions < ARCHIVE_PAYS_FROM) {
            return process;
        }
        Path archive = Files.createDirectory(work.resolve("archive"));
        Path archiveWork = Files.createDirectory(work.resolve("archive-run"));
        cohort.started(process);
        StudentProcess withArchive;
        try {
            withArchive = process.withSharedArchive(archive, archiveWork);
        } finally {
            cohort.ended(process);
            WorkFolder.delete(archiveWork);
        }
        WorkFolder.readableByAll(archive);
        return withArchive;
    }
}
