package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.ChildOutput;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.engine.io.IoErrors;
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
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
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
 * under a user of its own, start to finish. Each result is stored the moment it is known
 * ({@link ResultStore}), so a run that is stopped loses no finished result, and the next run grades
 * only what is left, new or changed. The grading scenes are read and their references rendered once.
 */
public final class CohortGrade {

    /**
     * What a cohort grade did: every result in the submissions' order, the images, how many results
     * were stored from earlier runs; {@code ungraded}, the submissions that could not be graded, each with why.
     */
    public record Done(List<StudentResult> results, List<Path> images, int stored, List<Ungraded> ungraded) {
    }

    final Grading grading;
    final Sandbox sandbox;
    private final int jobs;
    final ResultStore store;
    final PrintWriter err;
    private final ProgressLine line;
    private final List<StudentProcess> processes = Collections.synchronizedList(new ArrayList<>());
    private volatile boolean stopping;
    /** Counted down when {@link #run} has ended: every job's grade ended, and each result kept or deleted. */
    private final CountDownLatch runEnded = new CountDownLatch(1);
    /** The submissions whose results are in the store: from earlier runs, and graded whole by this one. */
    private final AtomicInteger kept = new AtomicInteger();

    /**
     * Grades with {@code grading}'s scenes and limits in {@code sandbox}, storing results in
     * {@code store}; {@code err} gets what a grade says there, and {@code line} how many are graded.
     */
    public CohortGrade(Grading grading, Sandbox sandbox, int jobs, ResultStore store, PrintWriter err,
            ProgressLine line) {
        this.grading = grading;
        this.sandbox = sandbox;
        this.jobs = jobs;
        this.store = store;
        this.err = err;
        this.line = line;
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

    /** Counts {@code process} among those {@link #stop()} stops, and stops it if stop() came first. */
    void started(StudentProcess process) {
        processes.add(process);
        if (stopping) {
            process.stop();   // stop() came before this process was there to stop
        }
    }

    /** No longer counts {@code process} among those {@link #stop()} stops. */
    void ended(StudentProcess process) {
        processes.remove(process);
    }

    /** Waits, at most {@code most}, for {@link #run} to end: what grades stop() cut short began to store is gone. */
    public void awaitEnd(Duration most) throws InterruptedException {
        runEnded.await(most.toMillis(), TimeUnit.MILLISECONDS);
    }

    /** How many submissions have their results stored: from earlier runs, and graded whole by this one. */
    public int kept() {
        return kept.get();
    }

    /** Grades {@code submissions} in {@code work}, a folder of the grader's own. */
    public Done run(List<Submission> submissions, Path work) throws IOException, InterruptedException {
        try {
            return new CohortRun(submissions, work).grade();
        } finally {
            runEnded.countDown();
        }
    }

    /** One run's state: what is to grade, what is known, and the jobs that grade it. */
    private final class CohortRun implements CohortJob.Results {
        private final List<Submission> submissions;
        private final Path work;
        private final StudentResult[] results;
        private final Path[] images;
        private final List<Integer> todo = new ArrayList<>();
        /** Submissions with the same key (the same files) are graded once: the others wait for its result. */
        private final Map<Integer, String> sameAsEarlier = new HashMap<>();
        private final Map<String, Integer> firstWithKey = new HashMap<>();
        private final List<Ungraded> ungraded = Collections.synchronizedList(new ArrayList<>());
        /** The jobs not grading just now: each has its own folder, sandbox user and process. */
        private final BlockingQueue<CohortJob> idle = new LinkedBlockingQueue<>();
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
                    String folder = submissions.get(firstWithKey.get(same.getValue())).folder();
                    Ungraded.Cause cause = ungraded.stream().filter(one -> one.folder().equals(folder))
                            .map(Ungraded::cause).findFirst().orElse(Ungraded.Cause.TICK1_ERROR);
                    ungraded.add(new Ungraded(submissions.get(i).folder(), "the same files as " + folder
                            + ", which was not graded", cause));
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
            return new Done(all, allImages, stored, List.copyOf(ungraded));
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
                    kept.incrementAndGet();
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
            StudentProcess shared = CohortJob.harness(CohortGrade.this, work, todo.size());
            int count = Math.min(jobs, todo.size());
            for (int job = 0; job < count; job++) {
                idle.add(new CohortJob(CohortGrade.this, job, work.resolve("job-" + job), shared));
            }
            Progress progress = new Progress(todo.size());
            ExecutorService pool = Executors.newFixedThreadPool(count, new JobThreads());
            try {
                // Each student start to finish (compile, public run, hidden run, result stored), so that a
                // stop keeps every student graded whole before it.
                List<Future<?>> grades = new ArrayList<>();
                for (int index : todo) {
                    grades.add(pool.submit(() -> grade(index, progress)));
                }
                awaitAll(grades);
            } finally {
                pool.shutdownNow();
                pool.awaitTermination(1, TimeUnit.MINUTES);
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

        /** Grades the {@code index}-th submission with an idle job, and stores its result. */
        private Void grade(int index, Progress progress) throws InterruptedException {
            if (stopping) {
                return null;
            }
            CohortJob job = idle.take();
            try {
                guarded(index, progress, () -> job.grade(submissions.get(index), index, this));
            } finally {
                idle.add(job);
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
            } catch (GraderShort | ReportUnwritable | OutOfMemoryError e) {
                if (!stopping) {
                    String why = e instanceof IOException ? e.getMessage() : "the grader ran out of memory (give it "
                            + "more with JAVA_OPTS=-Xmx...) and grade again";
                    Ungraded.Cause cause = e instanceof ReportUnwritable ? Ungraded.Cause.REPORT_FOLDER
                            : Ungraded.Cause.GRADER_SHORT;
                    ungraded.add(new Ungraded(submission.folder(), why, cause));
                    results[index] = StudentResult.notGraded(submission, cause == Ungraded.Cause.REPORT_FOLDER
                            ? "its result could not be stored in the report folder (" + why + ")" : why);
                    progress.done(false);
                }
            } catch (IOException | RuntimeException | Error e) {
                if (!stopping) {
                    String why = "an error in tick1 stopped its grade (" + ChildOutput.printable(
                            e.getClass().getSimpleName() + (e.getMessage() == null ? "" : ": " + e.getMessage()))
                            .replace('\n', ' ').lines().findFirst().orElse("") + ")";
                    why = why.length() > WHY_CAP ? why.substring(0, WHY_CAP) + "...)" : why;
                    ungraded.add(new Ungraded(submission.folder(), why, Ungraded.Cause.TICK1_ERROR));
                    results[index] = StudentResult.notGraded(submission, why);
                    progress.done(false);
                }
            }
        }

        @Override
        public void storeResult(int index, SubmissionGrader.Graded graded, Path entry) throws IOException {
            Submission submission = submissions.get(index);
            String key = ResultStore.key(submission, grading, sandbox.enforcement());
            if (graded.imagesUnwritable()) {
                throw new ReportUnwritable(ResultStore.refusal(entry));
            }
            try {
                store.save(key, graded.result(), entry);
            } catch (IOException e) {
                throw new ReportUnwritable(IoErrors.reason(e));
            }
            // Its twins' result too: theirs is the same, stored under the same key.
            kept.addAndGet(1 + Collections.frequency(sameAsEarlier.values(), key));
            results[index] = graded.result();
            images[index] = store.folderOf(key);
        }
    }

    /** One grade: its result, or null when stop() cut it short. */
    @FunctionalInterface
    private interface Step {
        StudentResult run() throws IOException, InterruptedException;
    }

    /** The most characters of why a submission could not be graded. */
    private static final int WHY_CAP = 200;

    /** The pool's threads, named by job, as the hand-made workers were. */
    private static final class JobThreads implements ThreadFactory {
        private final AtomicInteger next = new AtomicInteger();

        @Override
        public Thread newThread(Runnable task) {
            return new Thread(task, "tick1-grade-job-" + next.getAndIncrement());
        }
    }

    /** One updating line on the terminal: how many are graded, of how many, and how many failed. */
    private final class Progress {
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
