package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;

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
    private final Queue<Waiting> waiting = new ConcurrentLinkedQueue<>();
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
            jobSandbox.share(folder, false);
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
     * Begins {@code submission}'s grade: stores its result when the grade ends there, else
     * leaves it waiting for {@link #finish}. The result, or null when the grade waits or was
     * cut short by stop().
     */
    StudentResult begin(Submission submission, int index, Results run) throws IOException,
            InterruptedException {
        if (grader == null) {
            setUp();
        }
        Path submissionWork = Files.createDirectory(folder.resolve("submission-" + index));
        Path entry = cohort.store.newEntry();
        boolean waits = false;
        try {
            SubmissionGrader.Begun begun = grader.begin(submission, submissionWork, entry,
                    new PrintWriter(Writer.nullWriter()), cohort.err);
            if (begun instanceof SubmissionGrader.Halfway halfway) {
                waiting.add(new Waiting(index, submissionWork, entry, halfway.setAside(submissionWork)));
                waits = true;
                return null;
            }
            return stored(((SubmissionGrader.Finished) begun).graded(), index, entry, run);
        } catch (IOException | RuntimeException | Error e) {
            WorkFolder.delete(entry);
            throw e;
        } finally {
            if (!waits) {
                WorkFolder.delete(submissionWork);
            }
        }
    }

    /** Finishes a grade {@link #begin} left waiting, and stores its result; null when stop() cut it short. */
    StudentResult finish(Waiting grade, Results run) throws IOException, InterruptedException {
        try {
            return stored(grader.finish(grade.halfway(), grade.work(), new PrintWriter(Writer.nullWriter())),
                    grade.index(), grade.entry(), run);
        } catch (IOException | RuntimeException | Error e) {
            WorkFolder.delete(grade.entry());
            throw e;
        } finally {
            WorkFolder.delete(grade.work());
        }
    }

    /** Stores a grade's result in {@code entry}; null, with nothing stored, when stop() cut it short. */
    private StudentResult stored(SubmissionGrader.Graded graded, int index, Path entry, Results run)
            throws IOException, InterruptedException {
        String diskShort = graded.result().passed() ? null : GraderDisk.shortOfSpace(folder);
        if (diskShort != null) {
            WorkFolder.delete(entry);
            throw new GraderShort(diskShort);
        }
        // A grade cut short by stop() ended after stopping was set: it is never stored.
        if (cohort.stopped()) {
            WorkFolder.delete(entry);
            return null;
        }
        run.storeResult(index, graded, entry);
        return graded.result();
    }

    /** The next grade waiting for its hidden scenes, or null. */
    Waiting nextWaiting() {
        return waiting.poll();
    }

    /** Deletes what the grades still waiting would have stored: stop() cut them short. */
    void forgetWaiting() {
        for (Waiting grade = waiting.poll(); grade != null; grade = waiting.poll()) {
            WorkFolder.delete(grade.entry());
            WorkFolder.delete(grade.work());
        }
    }

    /** A grade begun and waiting for its hidden scenes: its submission, folders and first half. */
    record Waiting(int index, Path work, Path entry, SubmissionGrader.Halfway halfway) {
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
        readableByAll(harness);
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
        readableByAll(archive);
        return withArchive;
    }

    private static void readableByAll(Path folder) throws IOException {
        Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwxr-xr-x"));
        try (var files = Files.list(folder)) {
            for (Path file : files.toList()) {
                Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("r--r--r--"));
            }
        }
    }
}
