package gfx.tick1.command.shared.grader.sandbox;

import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.sandbox.Sandbox.Bind;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * One run of the harness's JVM in the {@link Sandbox}: the command, its limits per process and in
 * all (a control group of its own where one can be made), the wait for its end or its time limit,
 * the count of what it writes to its output folder, and the kill of everything it started.
 */
final class SandboxedProcess {

    /** How much of what the student's code printed is kept, from the end. */
    private static final int OUTPUT_TAIL_CHARS = 2000;
    /** How often the log of a run that compiles first is read, until it says the code compiled. */
    private static final long COMPILED_POLL_MILLIS = 10;
    /** How often the output folder is counted. */
    private static final long COUNT_EVERY_MILLIS = 100;
    /** Address space beyond the heap: the JVM's code, class metadata, thread stacks, libraries. */
    private static final int NON_HEAP_MEGABYTES = 1024;
    /** Memory for all of a run's processes together beyond the heap: the JVM's own, tmpfs, shared memory. */
    static final int TOTAL_BEYOND_HEAP_MEGABYTES = 512;

    /**
     * What to run: the harness's arguments; the folders bound in; the file system of the output
     * folder among them, whose caps the run is held to (or null: none is); its time; its JVM; and
     * the batch of scenes it renders (a hidden batch under the stricter seccomp filter:
     * {@link SeccompFilter}).
     * Made by {@link #of} and the methods that return a changed copy, in the order the folders are bound.
     */
    record Request(List<String> harnessArguments, List<Bind> binds, OutputDisk output, Time time, Jvm jvm,
            SceneBatch batch) {

        /** The harness run with {@code harnessArguments} in {@code jvm} within {@code timeLimit}, nothing bound in. */
        static Request of(List<String> harnessArguments, Duration timeLimit, Jvm jvm) {
            return new Request(List.copyOf(harnessArguments), List.of(), null, new Time(timeLimit, null), jvm,
                    SceneBatch.PUBLIC);
        }

        /** The same run with {@code folder} bound in, read-only, at {@code inside}. */
        Request reading(Path folder, String inside) {
            return withBinds(plus(new Bind(folder, inside, false)));
        }

        /** The same run with {@code folder} bound in, writable, at {@code inside}. */
        Request writing(Path folder, String inside) {
            return withBinds(plus(new Bind(folder, inside, true)));
        }

        /** The same run with {@code disk}'s folder bound in, writable, at {@code inside}, as its output folder. */
        Request output(OutputDisk disk, String inside) {
            return new Request(harnessArguments, plus(new Bind(disk.folder(), inside, true)), disk, time, jvm, batch);
        }

        /** The same run compiling first: its time limit starts again when {@code progress} says it compiled. */
        Request compilingFirst(Path progress) {
            return new Request(harnessArguments, binds, output, new Time(time.limit(), progress), jvm, batch);
        }

        /** The same run rendering {@code scenes}. */
        Request rendering(SceneBatch scenes) {
            return new Request(harnessArguments, binds, output, time, jvm, scenes);
        }

        /** The same run with {@code all} bound in instead. */
        Request withBinds(List<Bind> all) {
            return new Request(harnessArguments, List.copyOf(all), output, time, jvm, batch);
        }

        private List<Bind> plus(Bind bind) {
            List<Bind> all = new ArrayList<>(binds);
            all.add(bind);
            return all;
        }
    }

    /**
     * How long a run may take: {@code limit}; for a run that compiles first, the log {@code progress}
     * it writes (null for any other run), and as long again from the moment that says "compiled".
     */
    record Time(Duration limit, Path progress) {

        /** How long the run may go on once the harness logs that it compiled: none for a run that does not compile. */
        Duration thenLimit() {
            return progress == null ? Duration.ZERO : limit;
        }
    }

    /** The harness's JVM: its heap, whether it is held to one core (as the student's code is), its options. */
    record Jvm(int heapMegabytes, boolean oneCore, List<String> options) {
    }

    /**
     * How a run ended, and the end of what it printed (printable characters only); for a run that
     * compiles first, whether it was seen to finish compiling; and the total it reached, or null.
     */
    record Run(boolean finished, int exitStatus, String outputTail, boolean compiledSeen,
            LimitReached limitReached) {
    }

    private final Sandbox sandbox;
    private volatile Process running;
    private volatile boolean stopped;

    SandboxedProcess(Sandbox sandbox) {
        this.sandbox = sandbox;
    }

    /** Kills the run that is going, if one is, and every later one before it starts. */
    void stop() {
        stopped = true;
        Process process = running;
        if (process != null) {
            kill(process);
        }
    }

    /** Runs {@code command} (the JVM and its arguments, as outside the sandbox) as {@code request} says. */
    Run run(List<String> command, Request request) throws IOException, InterruptedException {
        if (stopped) {
            throw new InterruptedException("the grade was stopped");
        }
        Time time = request.time();
        int cpuSeconds = (int) Math.ceil(time.limit().plus(time.thenLimit()).toMillis() / 1000.0) + 1;
        try (Started started = start(sandbox, command, request.binds(), cpuSeconds, request.jvm(), request.batch())) {
            Process process = started.process();
            running = process;
            try {
                if (stopped) {
                    // stop() came between the start and the line above: it must still end this run.
                    throw new InterruptedException("the grade was stopped");
                }
                process.getOutputStream().close();
                OutputTail tail = new OutputTail(process.getInputStream());
                tail.start();
                Waited waited = await(process, request);
                if (!waited.finished()) {
                    kill(process);
                }
                tail.join(1000);
                kill(process);
                LimitReached reached = started.limitReached();
                // Counted once more now that nothing of the run's can write: what it wrote after the last
                // count, or in the moments before it ended, counts as much as what it wrote before.
                String over = waited.overOutputCap() != null ? waited.overOutputCap() : overCap(request);
                return new Run(waited.finished() && over == null, process.exitValue(),
                        ChildOutput.printable(tail.text()), waited.compiledAt() >= 0,
                        over != null ? new LimitReached(NoImage.DISK_LIMIT, over) : reached);
            } finally {
                running = null;
            }
        }
    }

    /**
     * A process started in the sandbox and not yet waited for, with its control group (or null);
     * closing it kills the process and everything it started, then removes the group.
     */
    record Started(Process process, Cgroup cgroup) implements AutoCloseable {

        /** The total the run reached, or null. */
        LimitReached limitReached() {
            return cgroup == null ? null : cgroup.limitReached();
        }

        @Override
        public void close() {
            kill(process);
            if (cgroup != null) {
                cgroup.close();
            }
        }
    }

    /**
     * Starts {@code command} in {@code sandbox} with {@code binds}, at most {@code cpuSeconds} of
     * processor time, the heap of {@code jvm} and the address space and totals that go with it; on
     * one core when it says so; for a hidden {@code batch}, under the hidden runs' filter. Its
     * standard streams are the caller's to use.
     */
    static Started start(Sandbox sandbox, List<String> command, List<Bind> binds, int cpuSeconds, Jvm jvm,
            SceneBatch batch) throws IOException {
        int heapMegabytes = jvm.heapMegabytes();
        boolean oneCore = jvm.oneCore();
        Cgroup cgroup = sandbox.cgroupFor(new Cgroup.Totals(
                (long) (heapMegabytes + TOTAL_BEYOND_HEAP_MEGABYTES) << 20, RunLimits.PROCESSES_LIMIT, oneCore));
        try {
            Process process = sandbox.process(sandbox.wrap(command, binds,
                    new RunLimits(cpuSeconds, heapMegabytes + NON_HEAP_MEGABYTES, oneCore), cgroup, batch))
                    .redirectErrorStream(true).start();
            return new Started(process, cgroup);
        } catch (IOException | RuntimeException e) {
            if (cgroup != null) {
                cgroup.close();
            }
            throw e;
        }
    }

    /** How the wait ended: whether the process did, when "compiled" was seen (or -1), what it wrote too much of. */
    private record Waited(boolean finished, long compiledAt, String overOutputCap) {
    }

    /**
     * Waits until the process ends or its time is up, reading the log of a run that compiles
     * first until it says "compiled" (polled: the harness cannot signal otherwise without a
     * channel the student's code could use later), and counting the output folder.
     */
    private static Waited await(Process process, Request request) throws IOException, InterruptedException {
        Time time = request.time();
        long start = System.nanoTime();
        long deadline = start + time.limit().toNanos();
        long compiledAt = -1, counted = start;
        while (true) {
            boolean polling = time.progress() != null && compiledAt < 0;
            boolean ended = process.waitFor(polling ? COMPILED_POLL_MILLIS : COUNT_EVERY_MILLIS, TimeUnit.MILLISECONDS);
            long now = System.nanoTime();
            if (polling) {
                String logged = ChildOutput.readText(time.progress());
                if (logged != null && logged.lines().anyMatch(StudentHarness.COMPILED::equals)) {
                    compiledAt = now;
                    deadline = now + time.thenLimit().toNanos();
                }
            }
            if (ended) {
                return new Waited(true, compiledAt, null);
            }
            if (now - counted >= TimeUnit.MILLISECONDS.toNanos(COUNT_EVERY_MILLIS)) {
                counted = now;
                String over = overCap(request);
                if (over != null) {
                    return new Waited(false, compiledAt, over);
                }
            }
            if (now - deadline >= 0) {
                return new Waited(false, compiledAt, null);
            }
        }
    }

    /** What the run holds beyond its output folder's caps, in words for the student, or null. */
    private static String overCap(Request request) {
        return request.output() == null ? null : request.output().overCap();
    }

    /**
     * Kills the process and everything it started, and returns when they are gone, so that no
     * process of the student's can change its output folder while it is read. (In the sandbox the
     * first of them is the PID namespace's init, which ends only after every other process in it.)
     */
    static void kill(Process process) {
        List<ProcessHandle> started = process.descendants().toList();
        started.forEach(ProcessHandle::destroyForcibly);
        process.destroyForcibly();
        try {
            process.waitFor();
            for (ProcessHandle handle : started) {
                handle.onExit().get(10, TimeUnit.SECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException | TimeoutException e) {
            // A process that will not die within seconds of SIGKILL: nothing more to do.
        }
    }

    /** The harness's command line for a run outside the sandbox: the folders keep their own names. */
    static List<String> unconfinedArguments(List<String> harnessArguments, List<Bind> binds) {
        List<String> real = new ArrayList<>();
        for (String argument : harnessArguments) {
            String named = argument;
            for (Bind bind : binds) {
                if (argument.equals(bind.inside()) || argument.startsWith(bind.inside() + "/")) {
                    named = bind.outside() + argument.substring(bind.inside().length());
                }
            }
            real.add(named);
        }
        return real;
    }

    /** Reads the child's output as it comes, keeping only the end, so no output can fill memory. */
    private static final class OutputTail extends Thread {
        private final InputStream in;
        private final StringBuilder text = new StringBuilder();

        OutputTail(InputStream in) {
            this.in = in;
            setDaemon(true);
        }

        @Override
        public void run() {
            byte[] buffer = new byte[8192];
            try {
                for (int n; (n = in.read(buffer)) > 0; ) {
                    synchronized (text) {
                        text.append(new String(buffer, 0, n, StandardCharsets.UTF_8));
                        if (text.length() > 2 * OUTPUT_TAIL_CHARS) {
                            text.delete(0, text.length() - OUTPUT_TAIL_CHARS);
                        }
                    }
                }
            } catch (IOException e) {
                // The child was killed: what was read is all there is.
            }
        }

        String text() {
            synchronized (text) {
                return text.length() > OUTPUT_TAIL_CHARS ? text.substring(text.length() - OUTPUT_TAIL_CHARS)
                        : text.toString();
            }
        }
    }
}
