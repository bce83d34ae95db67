package gfx.tick1.grade.cohort;

import gfx.tick1.grade.grading.Grading;
import gfx.tick1.grade.grading.SubmissionGrader;
import gfx.tick1.grade.model.StudentResult;
import gfx.tick1.grade.model.Submission;
import gfx.tick1.grade.sandbox.Sandbox;
import gfx.tick1.grade.sandbox.StudentProcess;
import gfx.tick1.grade.sandbox.WorkFolder;
import gfx.tick1.io.ProgressLine;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * Grades a cohort: every submission in the sandbox, {@code jobs} at a time, each in a process and
 * under a user of its own. Each result is stored the moment it is known ({@link ResultStore}), so
 * a run that is stopped loses no finished result, and the next run grades only what is new or
 * changed. The grading scenes are read and their reference images rendered once for everyone.
 */
public final class CohortGrade {

    /** What a cohort grade did: every result in the submissions' order, and the time of those graded now. */
    public record Done(List<StudentResult> results, List<Path> images, List<SubmissionGrader.Phases> phases, int stored,
            List<String> ungraded) {
    }

    /**
     * From how many submissions to grade a class data sharing archive is made: it takes about as
     * long as grading one, and saves a fifth of each grade's processor time.
     */
    private static final int ARCHIVE_PAYS_FROM = 8;

    private final Grading grading;
    private final Sandbox sandbox;
    private final int jobs;
    private final ResultStore store;
    private final PrintWriter err;
    private final boolean showProgress;
    private final List<StudentProcess> processes = Collections.synchronizedList(new ArrayList<>());
    private volatile boolean stopping;

    /**
     * Grades with {@code grading}'s scenes and limits in {@code sandbox}, storing results in
     * {@code store}; {@code showProgress} for an updating line on {@code err}.
     */
    public CohortGrade(Grading grading, Sandbox sandbox, int jobs, ResultStore store, PrintWriter err,
            boolean showProgress) {
        this.grading = grading;
        this.sandbox = sandbox;
        this.jobs = jobs;
        this.store = store;
        this.err = err;
        this.showProgress = showProgress;
    }

    /** Whether {@link #stop()} was called: the results are then not the whole cohort's. */
    public boolean stopped() {
        return stopping;
    }

    /**
     * Stops the grade (Ctrl-C, SIGTERM): kills every student's process that is running, and
     * makes sure that no result of a grade this cuts short is stored.
     */
    public void stop() {
        stopping = true;
        synchronized (processes) {
            processes.forEach(StudentProcess::stop);
        }
    }

    /** Grades {@code submissions} in {@code work}, a folder of the grader's own. */
    public Done run(List<Submission> submissions, Path work) throws IOException, InterruptedException {
        int count = submissions.size();
        StudentResult[] results = new StudentResult[count];
        Path[] images = new Path[count];
        List<Integer> todo = new ArrayList<>();
        // Submissions with the same key (the same files) are graded once: the others wait for its result.
        Map<Integer, String> sameAsEarlier = new HashMap<>();
        Set<String> keys = new HashSet<>();
        for (int i = 0; i < count; i++) {
            Submission submission = submissions.get(i);
            if (submission.problem() != null) {
                results[i] = new SubmissionGrader(grading, sandbox, null, null)
                        .grade(submission, null, null, new PrintWriter(Writer.nullWriter()), err).result();
                continue;
            }
            String key = ResultStore.key(submission, grading);
            results[i] = store.load(key, submission);
            if (results[i] == null && !keys.add(key)) {
                sameAsEarlier.put(i, key);
            } else if (results[i] == null) {
                todo.add(i);
            } else {
                images[i] = store.folderOf(key);
            }
        }
        int stored = (int) IntStream.range(0, count)
                .filter(i -> results[i] != null && submissions.get(i).problem() == null).count();
        List<SubmissionGrader.Phases> phases = Collections.synchronizedList(new ArrayList<>());
        List<String> ungraded = Collections.synchronizedList(new ArrayList<>());
        if (!todo.isEmpty()) {
            // The sandboxes' users must be able to pass through the work folder to their own folders in it.
            Files.setPosixFilePermissions(work, PosixFilePermissions.fromString("rwx--x--x"));
            StudentProcess process = process(work, todo.size());
            Progress progress = new Progress(todo.size());
            AtomicInteger next = new AtomicInteger();
            List<Thread> workers = new ArrayList<>();
            List<Throwable> failures = Collections.synchronizedList(new ArrayList<>());
            for (int job = 0; job < Math.min(jobs, todo.size()); job++) {
                int j = job;
                Thread worker = new Thread(() -> {
                    try {
                        work(j, work.resolve("job-" + j), process, submissions, todo, next, results, images, phases,
                                ungraded, progress);
                    } catch (IOException | RuntimeException e) {
                        if (!stopping) {
                            failures.add(e);
                        }
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }, "tick1-grade-job-" + j);
                workers.add(worker);
                worker.start();
            }
            for (Thread worker : workers) {
                worker.join();
            }
            progress.finish();
            if (!failures.isEmpty()) {
                Throwable first = failures.get(0);
                throw first instanceof IOException io ? io : new IOException(first.toString(), first);
            }
        }
        for (Map.Entry<Integer, String> same : sameAsEarlier.entrySet()) {
            results[same.getKey()] = store.load(same.getValue(), submissions.get(same.getKey()));
            images[same.getKey()] = store.folderOf(same.getValue());
        }
        List<StudentResult> all = new ArrayList<>();
        List<Path> allImages = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            if (results[i] != null) {
                all.add(results[i]);
                allImages.add(images[i]);
            }
        }
        return new Done(all, allImages, List.copyOf(phases), stored, List.copyOf(ungraded));
    }

    /** One job: its own folder, sandbox user and process; takes the next submission until none is left. */
    private void work(int job, Path folder, StudentProcess shared, List<Submission> submissions, List<Integer> todo,
            AtomicInteger next, StudentResult[] results, Path[] images, List<SubmissionGrader.Phases> phases,
            List<String> ungraded, Progress progress) throws IOException, InterruptedException {
        Sandbox jobSandbox = sandbox.forJob(job);
        Files.createDirectory(folder);
        grading.copyScenes(folder);
        jobSandbox.share(folder, false);
        StudentProcess process = shared.in(jobSandbox);
        processes.add(process);
        SubmissionGrader grader = new SubmissionGrader(grading, jobSandbox, process, folder);
        PrintWriter transcript = new PrintWriter(Writer.nullWriter());
        for (int n; !stopping && (n = next.getAndIncrement()) < todo.size(); ) {
            int index = todo.get(n);
            Submission submission = submissions.get(index);
            Path submissionWork = Files.createDirectory(folder.resolve("submission-" + index));
            Path entry = store.newEntry();
            SubmissionGrader.Graded graded;
            try {
                graded = grader.grade(submission, submissionWork, entry, transcript, err);
            } finally {
                WorkFolder.delete(submissionWork);
            }
            // A grade cut short by stop() ended after stopping was set: it is never stored.
            if (stopping) {
                return;
            }
            if (graded.imagesUnwritable()) {
                ungraded.add(submission.folder());
                WorkFolder.delete(entry);
            } else {
                store.save(ResultStore.key(submission, grading), graded.result(), entry);
                results[index] = graded.result();
                images[index] = store.folderOf(ResultStore.key(submission, grading));
                phases.add(graded.phases());
            }
            progress.done(graded.result().passed());
        }
    }

    /**
     * The harness every job runs, in {@code work}: one jar, and, when there are enough submissions
     * for it to pay, a class data sharing archive made for it. Both hold only this program's and the
     * JDK's classes, so every job's user may read them.
     */
    private StudentProcess process(Path work, int submissions) throws IOException, InterruptedException {
        Path harness = Files.createDirectory(work.resolve("harness"));
        StudentProcess.writeHarness(harness);
        readableByAll(harness);
        StudentProcess process = new StudentProcess(sandbox.forJob(0), harness, grading.limits().memoryMegabytes());
        if (submissions < ARCHIVE_PAYS_FROM || !process.compilesAndRendersInOneRun()) {
            return process;
        }
        Path archive = Files.createDirectory(work.resolve("archive"));
        Path archiveWork = Files.createDirectory(work.resolve("archive-run"));
        processes.add(process);
        StudentProcess withArchive;
        try {
            withArchive = process.withSharedArchive(archive, archiveWork);
        } finally {
            processes.remove(process);
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

    /** One updating line on the terminal: how many are graded, of how many, and how many failed. */
    private final class Progress {
        private final ProgressLine line = new ProgressLine(err, showProgress, Duration.ZERO, Duration.ZERO);
        private final int total;
        private int done, failed;

        Progress(int total) {
            this.total = total;
        }

        synchronized void done(boolean passed) {
            done++;
            failed += passed ? 0 : 1;
            line.show("grading: " + done + " of " + total + " (" + failed + " failed)");
        }

        void finish() {
            line.finish();
        }
    }
}
