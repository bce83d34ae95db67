package gfx.tick1.command.shared.grader.sandbox;

import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Run;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Started;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The warm compiler of one cohort job: a JVM in the sandbox that runs the harness's
 * {@code compile-server} and compiles submission after submission, so that javac's own warm-up,
 * most of a fresh JVM's compile, is paid once, not once a submission. No code of a student's runs
 * in it ({@code -proc:none}): it reads sources and writes class files, which the grader copies out
 * for the JVMs that run the code. It is started again after any compile that
 * did not succeed (an error, the time limit, memory, its end) and after
 * {@value #COMPILES_PER_START} compiles, so that no compile inherits a compiler in a bad state
 * and its processor-time limit stays that of a bounded number of compiles. It may write in the
 * output folder of the request it is compiling, and nowhere else: its folder and the requests'
 * are the grader's.
 *
 * <p>Its folder is a file system of its own where the sandbox can mount one ({@link
 * Sandbox#compilerDisk}), held by the kernel to a run's output caps: what a source makes javac
 * write (many classes, huge constants) fills that, never the grader's disk, and fails that
 * submission with the cap's words. Each request starts on an empty one: where something is left
 * (a compile the time limit stopped), the compiler is ended and a new file system mounted.
 */
final class CompileServer implements AutoCloseable {

    /** How many compiles one start of the compiler serves. */
    static final int COMPILES_PER_START = 100;
    /** The most characters of one line of the compiler's output that are kept. */
    private static final int LINE_CAP = 2000;
    private static final Pattern ANSWER = Pattern.compile(StudentHarness.COMPILED + " ([0-9]{1,9}) ([0-9]{1,3})");

    /**
     * Starts the compiler's JVM in {@code sandbox}, with {@code folder} bound writable, for compiles
     * of at most {@code timeLimit} each; its output is its answers.
     */
    interface Launcher {
        Started start(Sandbox sandbox, Path folder, Duration timeLimit) throws IOException;
    }

    private final Sandbox sandbox;
    private final Path folder;
    private final Launcher launcher;
    /** The file system of {@link #folder}, or null before the first request and once stopped. */
    private OutputDisk disk;
    private Started running;
    private volatile Answers answers;
    private int compiles;
    private int next;
    private volatile boolean stopped;

    /**
     * A compiler in {@code sandbox} started by {@code launcher}, exchanging requests through
     * {@code folder}, which the launcher binds writable.
     */
    CompileServer(Sandbox sandbox, Path folder, Launcher launcher) {
        this.sandbox = sandbox;
        this.folder = folder;
        this.launcher = launcher;
    }

    /**
     * A new request's folder, with an empty {@value StudentHarness#SOURCES_FOLDER} folder for its
     * sources, alone on the compiler's file system, and the folder {@link #takeOutput} moves its
     * output to (made now: a compile may leave no room for a folder); {@link #done} removes both.
     */
    synchronized Path newRequest() throws IOException, InterruptedException {
        if (stopped) {
            throw new InterruptedException("the grade was stopped");
        }
        if (disk == null || !disk.holdsNothing()) {
            // The compiler sees the file system it was started with: a new one needs a new compiler.
            close();
            WorkFolder.delete(folder);
            Files.createDirectory(folder);
            sandbox.share(folder);
            disk = sandbox.compilerDisk(folder);
        }
        Path request = Files.createDirectory(folder.resolve(Integer.toString(next++)));
        Files.createDirectory(request.resolve(StudentHarness.SOURCES_FOLDER));
        Files.createDirectory(taken(request), PosixFilePermissions.asFileAttribute(
                PosixFilePermissions.fromString("rwx------")));
        return request;
    }

    /**
     * Moves {@code request}'s output folder where the compiler cannot reach it, on the same file
     * system (it may still be running, and nothing it could write, a link or a FIFO in place of a
     * file, may change as it is read): a folder only the grader may enter. Returns the output
     * folder there, which is not there when nothing was written.
     */
    Path takeOutput(Path request) throws IOException {
        Path output = taken(request).resolve(StudentHarness.OUTPUT_FOLDER);
        try {
            Files.move(request.resolve(StudentHarness.OUTPUT_FOLDER), output, StandardCopyOption.ATOMIC_MOVE);
        } catch (NoSuchFileException e) {
            // Nothing written: read as such.
        }
        return output;
    }

    /** Removes {@code request} and what was taken of it, leaving the compiler's file system empty. */
    void done(Path request) {
        WorkFolder.delete(taken(request));
        WorkFolder.delete(request);
    }

    private static Path taken(Path request) {
        return request.resolveSibling(request.getFileName() + "-taken");
    }

    /**
     * Compiles the request whose sources are written, the two files reported as the names given,
     * within {@code timeLimit} (a start of the compiler included, when one is needed). The run
     * it answers with is read as a one-off compile's is, with {@code request}'s output folder.
     */
    Run compile(Path request, String sphereName, String rendererName, Duration timeLimit)
            throws IOException, InterruptedException {
        Files.writeString(request.resolve(StudentHarness.NAMES_FILE), sphereName + "\0" + rendererName,
                StandardCharsets.UTF_8);
        // The request's folders are the grader's, readable by the compiler: it may write in the output only.
        sandbox.share(request);
        long deadline = System.nanoTime() + timeLimit.toNanos();
        boolean servedOthers = servedOthers();
        Attempt first = attempt(request, timeLimit);
        Duration left = Duration.ofNanos(deadline - System.nanoTime());
        // A compiler that had compiled other submissions and ended without a word, at no total, may have
        // ended for reasons of its own (its processor time over its whole life): this source gets a fresh one.
        if (first.ended() && first.run().limitReached() == null && servedOthers && left.toMillis() > 0) {
            WorkFolder.delete(request.resolve(StudentHarness.OUTPUT_FOLDER));
            return attempt(request, left).run();
        }
        return first.run();
    }

    /** How one attempt at a compile ended, and whether the compiler ended with it before answering. */
    private record Attempt(Run run, boolean ended) {
    }

    private Attempt attempt(Path request, Duration timeLimit) throws IOException, InterruptedException {
        Path output = Files.createDirectory(request.resolve(StudentHarness.OUTPUT_FOLDER));
        sandbox.shareWritable(output);
        // This compile's own references: stop() may end the compiler meanwhile.
        Started compiler = ready(timeLimit);
        Answers heard = answers;
        String number = request.getFileName().toString();
        try {
            OutputStream requests = compiler.process().getOutputStream();
            requests.write((number + "\n").getBytes(StandardCharsets.US_ASCII));
            requests.flush();
        } catch (IOException e) {
            // The compiler is gone: its end, below, says how.
        }
        Answers.Heard answer = heard.await(number, timeLimit);
        if (answer == null) {
            endCompiler();
            return new Attempt(new Run(false, -1, heard.takeTail(), false, overCap(output)), false);
        }
        if (answer.status() == null) {
            compiler.process().waitFor(10, TimeUnit.SECONDS);
            LimitReached reached = compiler.limitReached();
            endCompiler();
            // A compiler that could not write its class files (its file system full) ends with an exception.
            LimitReached over = reached != null ? reached : overCap(output);
            return new Attempt(new Run(true, compiler.process().isAlive() ? -1 : compiler.process().exitValue(),
                    answer.tail(), false, over), true);
        }
        LimitReached over = overCap(output);
        if (over != null || answer.status() != 0
                || !ChildOutput.isDirectory(output.resolve(StudentHarness.CLASSES_FOLDER))) {
            // javac reports an Error it caught (a stack overflow, memory) as a failed compile, perhaps with
            // no word of it: after any compile that did not succeed, the next one gets a fresh compiler.
            endCompiler();
        }
        return new Attempt(new Run(over == null, answer.status(), answer.tail(), false, over), false);
    }

    /** The output folder's cap, when the compile left more than it allows in {@code output}; else null. */
    private LimitReached overCap(Path output) {
        OutputDisk counted;
        synchronized (this) {
            counted = disk;
        }
        String over = counted == null ? OutputCount.overCap(output) : counted.overCap(output);
        return over == null ? null : new LimitReached(NoImage.DISK_LIMIT, over);
    }

    /** Whether the compiler that takes the next compile has compiled others already. */
    private synchronized boolean servedOthers() {
        return running != null && running.process().isAlive() && compiles > 0 && compiles < COMPILES_PER_START;
    }

    /** The compiler that takes the next compile: the one running, or a new one when it cannot. */
    private synchronized Started ready(Duration timeLimit) throws IOException, InterruptedException {
        if (stopped) {
            throw new InterruptedException("the grade was stopped");
        }
        if (running == null || !running.process().isAlive() || compiles >= COMPILES_PER_START) {
            endCompiler();
            running = launcher.start(sandbox, folder, timeLimit);
            answers = new Answers(running.process().getInputStream());
            answers.start();
            compiles = 0;
        }
        compiles++;
        return running;
    }

    /** Ends the compiler and unmounts its file system, for good (on Ctrl-C or SIGTERM). */
    void stop() {
        stopped = true;
        close();
    }

    /** Ends the compiler and unmounts its file system; a later request starts both again. */
    @Override
    public synchronized void close() {
        endCompiler();
        if (disk != null) {
            disk.close();
            disk = null;
        }
    }

    /** Ends the compiler, for the next compile to start another on the same file system. */
    private synchronized void endCompiler() {
        if (running != null) {
            running.close();
            running = null;
        }
    }

    /**
     * Reads the compiler's output as it comes: its answers, each with what else it printed since
     * the one before (decoded as UTF-8, each line capped), and its end.
     */
    private static final class Answers extends Thread {
        /** An answer: the request and its status (null where the compiler ended), and what it printed before. */
        record Heard(String number, Integer status, String tail) {
        }

        private final InputStream in;
        private final BlockingQueue<Heard> answered = new LinkedBlockingQueue<>();
        private final StringBuilder tail = new StringBuilder();

        Answers(InputStream in) {
            this.in = in;
            setDaemon(true);
            setName("tick1-compiler-output");
        }

        @Override
        public void run() {
            ByteArrayOutputStream line = new ByteArrayOutputStream();
            try {
                for (int c; (c = in.read()) >= 0; ) {
                    if (c != '\n') {
                        if (line.size() < LINE_CAP) {
                            line.write(c);
                        }
                        continue;
                    }
                    String text = line.toString(StandardCharsets.UTF_8);
                    line.reset();
                    Matcher answer = ANSWER.matcher(text);
                    if (answer.matches()) {
                        answered.add(new Heard(answer.group(1), Integer.valueOf(answer.group(2)), takeTail()));
                    } else {
                        keep(text + "\n");
                    }
                }
            } catch (IOException e) {
                // The compiler was killed: what was read is all there is.
            }
            keep(line.toString(StandardCharsets.UTF_8));
            answered.add(new Heard(null, null, takeTail()));
        }

        private void keep(String text) {
            synchronized (tail) {
                tail.append(text);
                if (tail.length() > LINE_CAP) {
                    tail.delete(0, tail.length() - LINE_CAP);
                }
            }
        }

        /** What the compiler printed since its last answer, which the next answer will not carry. */
        String takeTail() {
            synchronized (tail) {
                String text = ChildOutput.printable(tail.toString());
                tail.setLength(0);
                return text;
            }
        }

        /** The compiler's answer to request {@code number}, its end (a null status), or null at {@code limit}. */
        Heard await(String number, Duration limit) throws InterruptedException {
            long deadline = System.nanoTime() + limit.toNanos();
            while (true) {
                Heard answer = answered.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS);
                if (answer == null || answer.status() == null || answer.number().equals(number)) {
                    return answer;
                }
            }
        }
    }
}
