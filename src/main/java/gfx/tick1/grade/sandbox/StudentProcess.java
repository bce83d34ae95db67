package gfx.tick1.grade.sandbox;

import gfx.tick1.grade.harness.StudentCompiler;
import gfx.tick1.grade.harness.StudentFile;
import gfx.tick1.grade.harness.StudentHarness;
import gfx.tick1.grade.sandbox.Sandbox.Bind;
import gfx.tick1.starter.StarterKit;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;

/**
 * Runs {@link StudentHarness} in a JVM of its own inside the {@link Sandbox}, with a heap limit and
 * a time limit, so that an infinite loop, a crash, or a call to System.exit in the student's code
 * is reported and never inherited, and so that the student's code can do nothing outside it. The
 * child is the same Java as this program; its class path is {@code /harness/harness.jar}, a jar
 * that holds the harness's classes and nothing else of this program. On the time limit the sandbox is killed,
 * and with it everything the student's code started.
 */
public final class StudentProcess {

    /** How much of what the student's code printed is kept, from the end. */
    private static final int OUTPUT_TAIL_CHARS = 2000;
    /** The compiler's heap when --memory is less: javac needs about this much for the starter code. */
    private static final int COMPILER_HEAP_MEGABYTES = 256;
    /** How often the log of a run that compiles first is read, until it says the code compiled. */
    private static final long COMPILED_POLL_MILLIS = 10;
    /** Address space beyond the heap: the JVM's code, class metadata, thread stacks, libraries. */
    private static final int NON_HEAP_MEGABYTES = 1024;

    /** Where the harness's classes, the compiled classes, scenes and output appear inside the sandbox. */
    static final String HARNESS = "/harness", SOURCES = "/sources", CLASSES = "/classes", SCENES = "/scenes",
            OUTPUT = "/output", ARCHIVE = "/archive";
    /** The harness's class path, a jar in the harness folder. */
    static final String HARNESS_JAR = "harness.jar";
    /** The class data sharing archive's name in its folder. */
    static final String SHARED_ARCHIVE = "harness.jsa";
    /** How long making the shared archive may take. */
    private static final Duration ARCHIVE_TIME_LIMIT = Duration.ofSeconds(60);

    /** What became of one scene. */
    public sealed interface Outcome {
        /** The student's code rendered this image. */
        record Rendered(BufferedImage image) implements Outcome {
        }

        /** No image: why, in words for the student. */
        record Failed(String reason) implements Outcome {
        }
    }

    /**
     * The outcome of every scene in order, and the last of what the student's code printed; each
     * scene's traced samples and the probes' log as the child wrote them (capped and printable, null
     * when there is none), for the grader to parse and judge.
     */
    public record Result(List<Outcome> outcomes, String outputTail, List<String> traces, String probes) {
    }

    /**
     * How a run of the harness ended, and the end of what it printed (printable characters only);
     * for a run that compiles first, whether it was seen to finish compiling and how long that took.
     */
    record Run(boolean finished, int exitStatus, String outputTail, boolean compiledSeen, long compileNanos) {
    }

    /** What compiling gave: the errors, or a reason the compiler did not finish, or neither (it compiled). */
    public record Compiled(List<String> errors, String failure) {
        public boolean compiled() {
            return errors.isEmpty() && failure == null;
        }
    }

    /** What a run that compiles and then renders gave: the compiling, and if it compiled, the images. */
    public record CompiledAndRendered(Compiled compiled, Result rendered, long compileNanos) {
    }

    private final Sandbox sandbox;
    private final Path harness;
    private final int memoryMegabytes;
    /** The folder holding {@value #SHARED_ARCHIVE}, or null. */
    private final Path sharedArchive;
    private volatile Process running;
    /** Set by {@link #stop}: no run starts after it. */
    private volatile boolean stopped;

    /**
     * Runs the harness whose classes are in {@code harness}, in {@code sandbox}, with
     * {@code memoryMegabytes} of heap.
     */
    public StudentProcess(Sandbox sandbox, Path harness, int memoryMegabytes) {
        this(sandbox, harness, memoryMegabytes, null);
    }

    private StudentProcess(Sandbox sandbox, Path harness, int memoryMegabytes, Path sharedArchive) {
        this.sandbox = sandbox;
        this.harness = harness;
        this.memoryMegabytes = memoryMegabytes;
        this.sharedArchive = sharedArchive;
    }

    /**
     * Compiles the {@code *.java} files of {@code sources} into {@code output}/classes, in the
     * sandbox; the student's files are reported as {@code sphereName} and {@code rendererName}.
     */
    public Compiled compile(Path sources, Path output, String sphereName, String rendererName, Duration timeLimit)
            throws IOException, InterruptedException {
        Run run = run(List.of("compile", SOURCES, OUTPUT, sphereName, rendererName),
                List.of(new Bind(sources, SOURCES, false), new Bind(output, OUTPUT, true)),
                timeLimit, null, Duration.ZERO, Math.max(memoryMegabytes, COMPILER_HEAP_MEGABYTES), false);
        return compiled(run, output, timeLimit);
    }

    /** Whether one JVM can compile and then run the code: its heap is enough for the compiler. */
    public boolean compilesAndRendersInOneRun() {
        return memoryMegabytes >= COMPILER_HEAP_MEGABYTES;
    }

    /**
     * Compiles as {@link #compile} does, then, in the same JVM, renders the scenes as {@link #render}
     * does: one JVM start instead of two. Compiling may take {@code timeLimit}, and rendering as
     * long again from the moment the harness logs that it compiled; until then no code of the
     * student's has run, so that line can be trusted. Only for scenes that are not hidden, as the
     * compiled classes stay in the output folder the code can write.
     */
    public CompiledAndRendered compileAndRender(Path sources, Path scenes, List<String> sceneFiles, Path output,
            String sphereName, String rendererName, int width, int height, Duration timeLimit, boolean probes)
            throws IOException, InterruptedException {
        List<String> arguments = new ArrayList<>(List.of("render", StudentHarness.COMPILE_FIRST, SOURCES,
                sphereName, rendererName, OUTPUT, Integer.toString(width), Integer.toString(height)));
        if (probes) {
            arguments.add(1, StudentHarness.PROBES);
        }
        sceneFiles.forEach(name -> arguments.add(SCENES + "/" + name));
        Run run = run(arguments, List.of(new Bind(sources, SOURCES, false), new Bind(scenes, SCENES, false),
                new Bind(output, OUTPUT, true)), timeLimit, output.resolve(StudentHarness.PROGRESS_FILE), timeLimit,
                memoryMegabytes, true);
        if (!run.compiledSeen()) {
            Compiled compiled = compiled(run, output, timeLimit);
            return new CompiledAndRendered(compiled.compiled()
                    ? new Compiled(List.of(), "the compiler stopped without logging that it had finished") : compiled,
                    null, run.compileNanos());
        }
        return new CompiledAndRendered(new Compiled(List.of(), null),
                rendered(run, output, sceneFiles, width, height, timeLimit), run.compileNanos());
    }

    /** What a run that compiled (or tried to) says about compiling. */
    private Compiled compiled(Run run, Path output, Duration timeLimit) throws IOException {
        if (!run.finished()) {
            return new Compiled(List.of(),
                    "the compiler did not finish within the time limit of " + describe(timeLimit));
        }
        if (run.exitStatus() == StudentHarness.DOES_NOT_COMPILE) {
            byte[] errors = ChildOutput.read(output.resolve(StudentHarness.ERRORS_FILE), ChildOutput.TEXT_CAP);
            if (errors != null && errors.length > 0) {
                List<String> list = Arrays.stream(new String(errors, StandardCharsets.UTF_8).split("\0"))
                        .map(ChildOutput::printable).toList();
                return list.equals(List.of(StudentCompiler.OUT_OF_MEMORY))
                        ? new Compiled(List.of(), StudentCompiler.OUT_OF_MEMORY + " (its heap limit is "
                                + Math.max(memoryMegabytes, COMPILER_HEAP_MEGABYTES) + " MiB)")
                        : new Compiled(list, null);
            }
        }
        if (run.outputTail().contains("OutOfMemoryError")) {
            return new Compiled(List.of(), StudentCompiler.OUT_OF_MEMORY + " (its heap limit is "
                    + Math.max(memoryMegabytes, COMPILER_HEAP_MEGABYTES) + " MiB)");
        }
        if (run.exitStatus() != 0 || !ChildOutput.isDirectory(output.resolve(StudentHarness.CLASSES_FOLDER))) {
            String said = run.outputTail().strip();
            return new Compiled(List.of(), "the compiler stopped with exit status " + run.exitStatus()
                    + (said.isEmpty() ? "" : ": " + said.lines().reduce((first, last) -> last).orElse("")));
        }
        return new Compiled(List.of(), null);
    }

    /**
     * Renders each scene with the compiled classes in {@code classes}; {@code output} is an empty
     * folder for the child's images and logs. The run may take {@code timeLeft}, what is left of
     * the grade's {@code timeLimit}. With {@code probes}, the harness also runs the probes.
     */
    public Result render(Path classes, Path scenes, List<String> sceneFiles, Path output, int width, int height,
            Duration timeLeft, Duration timeLimit, boolean probes) throws IOException, InterruptedException {
        List<String> arguments = new ArrayList<>(List.of("render", CLASSES, OUTPUT,
                Integer.toString(width), Integer.toString(height)));
        if (probes) {
            arguments.add(1, StudentHarness.PROBES);
        }
        sceneFiles.forEach(name -> arguments.add(SCENES + "/" + name));
        Run run = run(arguments, List.of(new Bind(classes, CLASSES, false), new Bind(scenes, SCENES, false),
                new Bind(output, OUTPUT, true)), timeLeft, null, Duration.ZERO, memoryMegabytes, true);
        return rendered(run, output, sceneFiles, width, height, timeLimit);
    }

    private Result rendered(Run run, Path output, List<String> sceneFiles, int width, int height, Duration timeLimit)
            throws IOException {
        String progressText = ChildOutput.readText(output.resolve(StudentHarness.PROGRESS_FILE));
        List<Outcome> outcomes = new ArrayList<>();
        for (int i = 0; i < sceneFiles.size(); i++) {
            outcomes.add(progressText == null && run.finished() && run.exitStatus() == 0
                    ? new Outcome.Failed("no image: the log of the run's progress is missing or is not a regular file "
                            + "(did the code remove or replace it?)")
                    : outcome(output, i, progressText == null ? List.of() : progressText.lines().toList(), run,
                            width, height, timeLimit));
        }
        List<String> traces = new ArrayList<>();
        for (int i = 0; i < sceneFiles.size(); i++) {
            traces.add(ChildOutput.readText(output.resolve(i + StudentHarness.TRACE_SUFFIX)));
        }
        return new Result(outcomes, run.outputTail(), traces,
                ChildOutput.readText(output.resolve(StudentHarness.PROBES_FILE)));
    }

    /**
     * Writes the harness's class path into {@code folder}, as {@value #HARNESS_JAR}: the class
     * files of {@link StudentHarness#CLASSES} ({@link StudentHarness}, {@link StudentCompiler},
     * {@link StudentFile}, and those that call the student's methods), their nested classes, and
     * nothing else of this program (no reference renderer, no scenes, no images for
     * the student's code to use). A jar, not a folder, as Java's class data sharing needs one.
     */
    public static void writeHarness(Path folder) throws IOException {
        try (JarOutputStream jar = new JarOutputStream(Files.newOutputStream(folder.resolve(HARNESS_JAR)))) {
            for (Class<?> top : StudentHarness.CLASSES) {
                for (Class<?> type : top.getNestMembers()) {
                    String file = type.getName().replace('.', '/') + ".class";
                    try (InputStream in = type.getResourceAsStream("/" + file)) {
                        if (in == null) {
                            throw new IOException("cannot find this program's own class " + file);
                        }
                        jar.putNextEntry(new JarEntry(file));
                        jar.write(in.readAllBytes());
                        jar.closeEntry();
                    }
                }
            }
        }
    }

    /**
     * Makes a class data sharing archive for the harness in {@code folder}: a run of the harness,
     * in the sandbox, that compiles the untouched starter kit and renders a tiny scene with it,
     * and writes every class it loaded (javac's included) into {@value #SHARED_ARCHIVE}. A JVM
     * that maps the archive starts and compiles quicker. Only the starter kit runs, so the archive
     * holds nothing of any student's; the sandbox is used only so that the paths are the ones
     * every later run sees. {@code work} is an empty folder for the run.
     *
     * @return the process, as this one but with the archive; or this one when the archive could
     *     not be made (Java then starts as it always does)
     */
    public StudentProcess withSharedArchive(Path folder, Path work) throws IOException, InterruptedException {
        Path sources = Files.createDirectory(work.resolve("sources"));
        for (String given : StarterKit.GIVEN_CLASSES) {
            Files.writeString(sources.resolve(given + ".java"), StarterKit.source(given), StandardCharsets.UTF_8);
        }
        for (String student : List.of("Sphere", "Renderer")) {
            Files.writeString(sources.resolve(student + ".java"), StarterKit.source(student), StandardCharsets.UTF_8);
        }
        Path scenes = Files.createDirectory(work.resolve("scenes"));
        Files.writeString(scenes.resolve("0.xml"), "<scene><point-light/><sphere z=\"4\"/></scene>\n");
        sandbox.share(work, false);
        Path output = Files.createDirectory(work.resolve("output"));
        sandbox.share(output, true);
        // With the probes, so that the classes they load are in the archive too.
        Run run = run(List.of("render", StudentHarness.PROBES, StudentHarness.COMPILE_FIRST, SOURCES, "Sphere.java",
                "Renderer.java", OUTPUT,
                "8", "6", SCENES + "/0.xml"), List.of(new Bind(sources, SOURCES, false),
                new Bind(scenes, SCENES, false), new Bind(output, OUTPUT, true)), ARCHIVE_TIME_LIMIT, null,
                Duration.ZERO, Math.max(memoryMegabytes, COMPILER_HEAP_MEGABYTES), false,
                List.of("-XX:ArchiveClassesAtExit=" + inside(output, OUTPUT) + "/" + SHARED_ARCHIVE));
        Path archive = output.resolve(SHARED_ARCHIVE);
        if (!run.finished() || !ChildOutput.isRegularFile(archive)) {
            return this;
        }
        Files.move(archive, folder.resolve(SHARED_ARCHIVE));
        Files.setPosixFilePermissions(folder.resolve(SHARED_ARCHIVE), PosixFilePermissions.fromString("r--r--r--"));
        return new StudentProcess(sandbox, harness, memoryMegabytes, folder);
    }

    /** The same process for another sandbox (a job's), with the same harness and archive. */
    public StudentProcess in(Sandbox other) {
        return new StudentProcess(other, harness, memoryMegabytes, sharedArchive);
    }

    /** Where {@code folder}, bound at {@code insideName}, is seen by the harness. */
    private String inside(Path folder, String insideName) {
        return sandbox.isConfined() ? insideName : folder.toString();
    }

    /** Kills the sandbox that is running, if one is (on Ctrl-C or SIGTERM). */
    public void stop() {
        stopped = true;
        Process process = running;
        if (process != null) {
            kill(process);
        }
    }

    /**
     * Runs the harness; {@code studentCode} when it runs the student's code (on one core), not only
     * javac. When {@code progress} is given, the run may take {@code timeLimit} until the harness
     * logs "compiled" there, and {@code thenLimit} from then on; otherwise {@code timeLimit} in all.
     */
    private Run run(List<String> harnessArguments, List<Bind> binds, Duration timeLimit, Path progress,
            Duration thenLimit, int heapMegabytes, boolean studentCode) throws IOException, InterruptedException {
        return run(harnessArguments, binds, timeLimit, progress, thenLimit, heapMegabytes, studentCode,
                sharedArchive == null ? List.of()
                        : List.of("-XX:SharedArchiveFile=" + inside(sharedArchive, ARCHIVE) + "/" + SHARED_ARCHIVE));
    }

    /** As above, with {@code javaOptions} for the JVM. */
    private Run run(List<String> harnessArguments, List<Bind> binds, Duration timeLimit, Path progress,
            Duration thenLimit, int heapMegabytes, boolean studentCode, List<String> javaOptions)
            throws IOException, InterruptedException {
        if (stopped) {
            throw new InterruptedException("the grade was stopped");
        }
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + heapMegabytes + "m",
                "-XX:MaxDirectMemorySize=32m",
                "-XX:CompressedClassSpaceSize=64m",
                "-XX:ReservedCodeCacheSize=64m",
                "-XX:+UseSerialGC",               // one GC thread: the student's code is single-threaded
                "-XX:TieredStopAtLevel=1",        // quick start; small renders are over before C2 pays
                "-XX:-UsePerfData",               // no shared-memory file in /tmp (there is no /tmp)
                "-Djava.awt.headless=true",
                "-Djava.io.tmpdir=" + (sandbox.isConfined() ? OUTPUT : System.getProperty("java.io.tmpdir")),
                "-cp", inside(harness, HARNESS) + "/" + HARNESS_JAR));
        command.addAll(javaOptions);
        command.add(StudentHarness.class.getName());
        if (sandbox.isConfined()) {
            command.addAll(harnessArguments);
        } else {
            // Without a sandbox the folders keep their own names.
            List<Bind> all = new ArrayList<>(binds);
            for (String argument : harnessArguments) {
                String real = argument;
                for (Bind bind : all) {
                    if (argument.equals(bind.inside()) || argument.startsWith(bind.inside() + "/")) {
                        real = bind.outside() + argument.substring(bind.inside().length());
                    }
                }
                command.add(real);
            }
        }
        List<Bind> allBinds = new ArrayList<>(binds);
        allBinds.add(new Bind(harness, HARNESS, false));
        if (sharedArchive != null) {
            allBinds.add(new Bind(sharedArchive, ARCHIVE, false));
        }
        int cpuSeconds = (int) Math.ceil(timeLimit.plus(thenLimit).toMillis() / 1000.0) + 1;
        Process process = Sandbox.processFor(sandbox.wrap(command, allBinds, cpuSeconds,
                heapMegabytes + NON_HEAP_MEGABYTES, studentCode)).redirectErrorStream(true).start();
        running = process;
        try {
            if (stopped) {
                // stop() came between the start and the line above: it must still end this run.
                throw new InterruptedException("the grade was stopped");
            }
            process.getOutputStream().close();
            OutputTail tail = new OutputTail(process.getInputStream());
            tail.start();
            long start = System.nanoTime();
            long compiledAt = progress == null ? -1 : awaitCompiled(process, progress, start + timeLimit.toNanos());
            boolean finished = compiledAt < 0 && progress != null ? !process.isAlive()
                    : process.waitFor(progress == null ? timeLimit.toMillis()
                            : thenLimit.toMillis() - (System.nanoTime() - compiledAt) / 1_000_000,
                            TimeUnit.MILLISECONDS);
            if (!finished) {
                kill(process);
            }
            tail.join(1000);
            return new Run(finished, process.exitValue(), ChildOutput.printable(tail.text()), compiledAt >= 0,
                    (compiledAt >= 0 ? compiledAt : System.nanoTime()) - start);
        } finally {
            kill(process);
            running = null;
        }
    }

    /**
     * Waits until the harness logs "compiled" in {@code progress}, the process ends, or the
     * deadline passes; the time it was seen, or -1. The log is polled: the harness cannot signal
     * otherwise without a channel the student's code could use later.
     */
    private static long awaitCompiled(Process process, Path progress, long deadline) throws IOException,
            InterruptedException {
        while (true) {
            boolean ended = process.waitFor(COMPILED_POLL_MILLIS, TimeUnit.MILLISECONDS);
            String logged = ChildOutput.readText(progress);
            if (logged != null && logged.lines().anyMatch(StudentHarness.COMPILED::equals)) {
                return System.nanoTime();
            }
            if (ended || System.nanoTime() - deadline >= 0) {
                return -1;
            }
        }
    }

    /**
     * Kills the process and everything it started, and returns when they are gone, so that no
     * process of the student's can change its output folder while it is read. (In the sandbox the
     * first of them is the PID namespace's init, which ends only after every other process in it.)
     */
    private static void kill(Process process) {
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
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            // A process that will not die within seconds of SIGKILL: nothing more to do.
        }
    }

    private static Outcome outcome(Path output, int index, List<String> progress, Run run, int width, int height,
            Duration timeLimit) throws IOException {
        Path image = output.resolve(index + ".png");
        String error = ChildOutput.readText(output.resolve(index + ".error"));
        if (error != null) {
            return new Outcome.Failed("the code threw " + error);
        }
        if (progress.contains("end " + index) && ChildOutput.isRegularFile(image)) {
            try {
                return new Outcome.Rendered(ChildOutput.readPng(image, width, height));
            } catch (ChildOutput.Unusable e) {
                return new Outcome.Failed("the image written for this scene is unusable: " + e.getMessage());
            }
        }
        if (!run.finished()) {
            if (!progress.contains("start " + index) && index > 0) {
                return new Outcome.Failed("not rendered: the time limit was reached at an earlier scene");
            }
            return new Outcome.Failed("no image within the time limit of " + describe(timeLimit)
                    + " (an infinite loop?); the program was stopped");
        }
        if (!progress.contains("start " + index)) {
            return new Outcome.Failed("not rendered: the run stopped at an earlier scene");
        }
        int exitStatus = run.exitStatus();
        return new Outcome.Failed("the program ended while rendering this scene, with exit status " + exitStatus
                + (exitStatus == 0 ? " (does the code call System.exit?)" : " (System.exit, or the JVM crashed)"));
    }

    static String describe(Duration duration) {
        long millis = duration.toMillis();
        return millis % 1000 == 0 ? millis / 1000 + " s" : millis / 1000.0 + " s";
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
