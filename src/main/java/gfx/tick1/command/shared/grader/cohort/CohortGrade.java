package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.ChildOutput;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.engine.io.ProgressLine;
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
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Grades a cohort: every submission in the sandbox, {@code jobs} at a time, each in a process and
 * under a user of its own. Each result is stored the moment it is known ({@link ResultStore}), so
 * a run that is stopped loses no finished result, and the next run grades only what is new or
 * changed. The grading scenes are read and their reference images rendered once for everyone.
 */
public final class CohortGrade {

    /**
     * What a cohort grade did: every result in the submissions' order, and the time of those graded
     * now; {@code ungraded}, the submissions that could not be graded, each with why.
     */
    public record Done(List<StudentResult> results, List<Path> images, List<SubmissionGrader.Phases> phases, int stored,
            List<Ungraded> ungraded) {
    }

    /**
     * A submission that could not be graded: its folder, and why in one line. It keeps a failing
     * row (never "no submission"), and is graded again by the next run.
     *
     * @param grader whether the grader is at fault (an error of tick1's), not the report's folder
     */
    public record Ungraded(String folder, String why, boolean grader) {
    }


    /**
     * From how many submissions to grade a class data sharing archive is made: it takes about as
     * long as grading one, and saves each scene's JVM about a fifteenth of its processor time
     * (0.29 against 0.31 CPU seconds at 640 x 480) and each warm compiler's start more.
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
        return new CohortRun(submissions, work).grade();
    }

    /** One run's state: what is to grade, what is known, and the jobs that grade it. */
    private final class CohortRun {
        private final List<Submission> submissions;
        private final Path work;
        private final StudentResult[] results;
        private final Path[] images;
        private final List<Integer> todo = new ArrayList<>();
        /** Submissions with the same key (the same files) are graded once: the others wait for its result. */
        private final Map<Integer, String> sameAsEarlier = new HashMap<>();
        private final Map<String, Integer> firstWithKey = new HashMap<>();
        private final List<SubmissionGrader.Phases> phases = Collections.synchronizedList(new ArrayList<>());
        private final List<Ungraded> ungraded = Collections.synchronizedList(new ArrayList<>());
        /** The jobs not grading just now: each has its own folder, sandbox user and process. */
        private final BlockingQueue<Job> idle = new LinkedBlockingQueue<>();
        private int stored;

        CohortRun(List<Submission> submissions, Path work) {
            this.submissions = submissions;
            this.work = work;
            this.results = new StudentResult[submissions.size()];
            this.images = new Path[submissions.size()];
        }

        Done grade() throws IOException, InterruptedException {
            triage();
            if (!todo.isEmpty()) {
                gradeTodo();
            }
            for (Map.Entry<Integer, String> same : sameAsEarlier.entrySet()) {
                int i = same.getKey();
                results[i] = store.load(same.getValue(), submissions.get(i));
                images[i] = store.folderOf(same.getValue());
                StudentResult original = results[firstWithKey.get(same.getValue())];
                if (results[i] == null && original != null && !original.graded()) {
                    // The one graded for it could not be: it fares the same.
                    results[i] = new StudentResult(submissions.get(i), new StudentResult.Summary(false, 0, 0,
                            original.diagnosis(), original.reason()), List.of(), Duration.ZERO);
                    ungraded.add(new Ungraded(submissions.get(i).folder(), "the same files as "
                            + submissions.get(firstWithKey.get(same.getValue())).folder() + ", which was not graded",
                            true));
                }
            }
            List<StudentResult> all = new ArrayList<>();
            List<Path> allImages = new ArrayList<>();
            for (int i = 0; i < results.length; i++) {
                if (results[i] != null) {
                    all.add(results[i]);
                    allImages.add(images[i]);
                }
            }
            return new Done(all, allImages, List.copyOf(phases), stored, List.copyOf(ungraded));
        }

        /** Results known already (problems, stored results), and the submissions left to grade. */
        private void triage() throws IOException, InterruptedException {
            for (int i = 0; i < submissions.size(); i++) {
                Submission submission = submissions.get(i);
                if (submission.problem() != null) {
                    results[i] = new SubmissionGrader(grading, sandbox, null, null)
                            .grade(submission, null, null, new PrintWriter(Writer.nullWriter()), err).result();
                    continue;
                }
                String key = ResultStore.key(submission, grading, sandbox.enforcement());
                results[i] = store.load(key, submission);
                if (results[i] != null) {
                    images[i] = store.folderOf(key);
                    stored++;
                } else if (firstWithKey.putIfAbsent(key, i) != null) {
                    sameAsEarlier.put(i, key);
                } else {
                    todo.add(i);
                }
            }
        }

        /** Grades {@link #todo} on a pool of {@code jobs} threads, one job (folder, user, process) each. */
        private void gradeTodo() throws IOException, InterruptedException {
            // The sandboxes' users must be able to pass through the work folder to their own folders in it.
            Files.setPosixFilePermissions(work, PosixFilePermissions.fromString("rwx--x--x"));
            StudentProcess shared = process(work, todo.size());
            int count = Math.min(jobs, todo.size());
            for (int job = 0; job < count; job++) {
                idle.add(new Job(job, work.resolve("job-" + job), shared));
            }
            Progress progress = new Progress(todo.size());
            ExecutorService pool = Executors.newFixedThreadPool(count, new JobThreads());
            try {
                // Every public run before any hidden one: the runs a student's report quotes then never come
                // after a run that had a hidden scene, nor run beside one, so none can time it or feel it use
                // the processor, whatever order the jobs take the submissions in.
                List<Future<?>> begun = new ArrayList<>();
                for (int index : todo) {
                    begun.add(pool.submit(() -> begin(index, progress)));
                }
                awaitAll(begun);
                List<Future<?>> finished = new ArrayList<>();
                for (Job job : idle) {
                    finished.add(pool.submit(() -> finishAll(job, progress)));
                }
                awaitAll(finished);
            } finally {
                pool.shutdownNow();
                pool.awaitTermination(1, TimeUnit.MINUTES);
                idle.forEach(Job::forgetWaiting);   // grades stop() cut short between their halves
                synchronized (processes) {
                    processes.forEach(StudentProcess::close);   // the jobs' warm compilers
                }
                progress.finish();
            }
        }

        private void awaitAll(List<Future<?>> tasks) throws InterruptedException {
            for (Future<?> one : tasks) {
                try {
                    one.get();
                } catch (ExecutionException e) {
                    // stop() ends the jobs' processes, and a grade it cut short ends with an interruption.
                    if (!(stopping && e.getCause() instanceof InterruptedException)) {
                        throw new IllegalStateException("a cohort job failed outside any grade", e.getCause());
                    }
                }
            }
        }

        /** Begins the {@code index}-th submission's grade with an idle job: its public scenes. */
        private Void begin(int index, Progress progress) throws InterruptedException {
            if (stopping) {
                return null;
            }
            Job job = idle.take();
            try {
                guarded(index, progress, () -> job.begin(submissions.get(index), index, this));
            } finally {
                idle.add(job);
            }
            return null;
        }

        /** Finishes, one after the other, the grades {@code job} began and left waiting for their hidden scenes. */
        private Void finishAll(Job job, Progress progress) throws InterruptedException {
            for (Job.Waiting waiting = job.nextWaiting(); waiting != null && !stopping; waiting = job.nextWaiting()) {
                Job.Waiting grade = waiting;
                guarded(grade.index(), progress, () -> job.finish(grade, this));
            }
            return null;
        }

        /**
         * Does one step of the {@code index}-th submission's grade. Whatever goes wrong in it is that
         * submission's failure, with a reason; the cohort goes on.
         */
        private void guarded(int index, Progress progress, Step step) throws InterruptedException {
            Submission submission = submissions.get(index);
            try {
                StudentResult result = step.run();
                if (result != null) {
                    progress.done(result.passed());
                }
            } catch (IOException | RuntimeException | Error e) {
                if (!stopping) {
                    String why = "an error in tick1 stopped its grade (" + ChildOutput.printable(
                            e.getClass().getSimpleName() + (e.getMessage() == null ? "" : ": " + e.getMessage()))
                            .replace('\n', ' ').lines().findFirst().orElse("") + ")";
                    why = why.length() > WHY_CAP ? why.substring(0, WHY_CAP) + "...)" : why;
                    ungraded.add(new Ungraded(submission.folder(), why, true));
                    results[index] = notGraded(submission, why);
                    progress.done(false);
                }
            }
        }

        void storeResult(int index, Submission submission, SubmissionGrader.Graded graded, Path entry)
                throws IOException {
            if (graded.imagesUnwritable()) {
                ungraded.add(new Ungraded(submission.folder(), "its images could not be stored in",
                        false));
                WorkFolder.delete(entry);
                return;
            }
            String key = ResultStore.key(submission, grading, sandbox.enforcement());
            store.save(key, graded.result(), entry);
            results[index] = graded.result();
            images[index] = store.folderOf(key);
            phases.add(graded.phases());
        }
    }

    /** One step of a grade: its result, or null when there is none yet or stop() cut it short. */
    @FunctionalInterface
    private interface Step {
        StudentResult run() throws IOException, InterruptedException;
    }

    /** The most characters of why a submission could not be graded. */
    private static final int WHY_CAP = 200;

    /** The failing result of a submission that could not be graded: a row that says so. */
    private StudentResult notGraded(Submission submission, String why) {
        return StudentResult.notGraded(submission, why);
    }

    /**
     * One job: a folder, a sandbox user and a process of its own, made when it first grades, with
     * a warm compiler that compiles every submission the job grades.
     */
    private final class Job {
        private final int number;
        private final Path folder;
        private final StudentProcess shared;
        private final Queue<Waiting> waiting = new ConcurrentLinkedQueue<>();
        private SubmissionGrader grader;

        Job(int number, Path folder, StudentProcess shared) {
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
                Sandbox jobSandbox = sandbox.forJob(number);
                Files.createDirectory(folder);
                grading.copyScenes(folder);
                jobSandbox.share(folder, false);
                StudentProcess process = shared.in(jobSandbox).withWarmCompiler(compilerFolder);
                processes.add(process);
                if (stopping) {
                    process.stop();   // stop() came before this job's process was there to stop
                }
                grader = new SubmissionGrader(grading, jobSandbox, process, folder);
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
        StudentResult begin(Submission submission, int index, CohortRun run) throws IOException,
                InterruptedException {
            if (grader == null) {
                setUp();
            }
            Path submissionWork = Files.createDirectory(folder.resolve("submission-" + index));
            Path entry = store.newEntry();
            boolean waits = false;
            try {
                SubmissionGrader.Begun begun = grader.begin(submission, submissionWork, entry,
                        new PrintWriter(Writer.nullWriter()), err);
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
        StudentResult finish(Waiting grade, CohortRun run) throws IOException, InterruptedException {
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
        private StudentResult stored(SubmissionGrader.Graded graded, int index, Path entry, CohortRun run)
                throws IOException, InterruptedException {
            String diskShort = graded.result().passed() ? null : GraderDisk.shortOfSpace(folder);
            if (diskShort != null) {
                WorkFolder.delete(entry);
                throw new IOException(diskShort);
            }
            // A grade cut short by stop() ended after stopping was set: it is never stored.
            if (stopping) {
                WorkFolder.delete(entry);
                return null;
            }
            run.storeResult(index, run.submissions.get(index), graded, entry);
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
    }

    /** The pool's threads, named by job, as the hand-made workers were. */
    private static final class JobThreads implements ThreadFactory {
        private final AtomicInteger next = new AtomicInteger();

        @Override
        public Thread newThread(Runnable task) {
            return new Thread(task, "tick1-grade-job-" + next.getAndIncrement());
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
        if (submissions < ARCHIVE_PAYS_FROM) {
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
