package gfx.tick1.command.shared.grader.sandbox;

import gfx.tick1.command.shared.grader.harness.StudentCompiler;
import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.sandbox.Sandbox.Bind;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Jvm;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Request;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Run;
import gfx.tick1.command.shared.kit.StarterKit;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
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
public final class StudentProcess implements AutoCloseable {

    /** The first heap of every JVM the harness runs in; it grows up to -Xmx as the code needs. */
    private static final int FIRST_HEAP_MEGABYTES = 32;
    /** The compiler's heap when --memory is less: javac needs about this much for the starter code. */
    private static final int COMPILER_HEAP_MEGABYTES = 256;

    /** Where the harness's classes, the compiled classes, scenes and output appear inside the sandbox. */
    static final String HARNESS = "/harness", SOURCES = "/sources", CLASSES = "/classes", SCENES = "/scenes",
            OUTPUT = "/output", ARCHIVE = "/archive", COMPILER = "/compiler";
    /** The harness's class path, a jar in the harness folder. */
    static final String HARNESS_JAR = "harness.jar";
    /** The class data sharing archive's name in its folder. */
    static final String SHARED_ARCHIVE = "harness.jsa";
    /**
     * The scene the shared archive's run renders: one the starter kit's SceneLoader accepts (every
     * colour given), so that the DOM parser, the image classes and ImageIO's PNG writer are archived
     * along with javac.
     */
    private static final String ARCHIVE_SCENE = "<scene><ambient-light colour=\"#202020\"/>"
            + "<point-light x=\"1\" y=\"1\" colour=\"#FFFFFF\"/><sphere z=\"4\" colour=\"#FF0000\"/></scene>\n";
    /** How long making the shared archive may take. */
    private static final Duration ARCHIVE_TIME_LIMIT = Duration.ofSeconds(60);

    /** What became of one scene. */
    public sealed interface Outcome {
        /** The student's code rendered this image. */
        record Rendered(BufferedImage image) implements Outcome {
        }

        /**
         * No image: why, as a kind and in words for the student; whether the run also reached its total of
         * processes and threads (which does not stop it, so the scene's own failure stands beside it).
         */
        record Failed(NoImage why, String reason, boolean atProcessLimit) implements Outcome {
            public Failed(NoImage why, String reason) {
                this(why, reason, false);
            }
        }
    }

    /**
     * The outcome of every scene in order, and the last of what the student's code printed; each
     * scene's traced samples and the probes' log as the child wrote them (capped and printable, null
     * when there is none), for the grader to parse and judge.
     */
    public record Result(List<Outcome> outcomes, String outputTail, List<String> traces, String probes) {
    }

    /** What compiling gave: the errors, or a reason the compiler did not finish, or neither (it compiled). */
    public record Compiled(List<String> errors, String failure) {
        public boolean compiled() {
            return errors.isEmpty() && failure == null;
        }
    }

    /** What a run that compiles and then renders gave: the compiling, and if it compiled, the images. */
    public record CompiledAndRendered(Compiled compiled, Result rendered) {
    }

    /**
     * The scenes one run renders: the files {@code sceneFiles} in the folder {@code scenes}, at
     * {@code width} x {@code height}; with {@code probes}, the harness also runs the probes. The
     * organiser's hidden scenes ({@code hidden}) render under the stricter seccomp filter.
     */
    public record Batch(Path scenes, List<String> sceneFiles, int width, int height, boolean probes, boolean hidden) {
    }

    private final Sandbox sandbox;
    private final Path harness;
    private final int memoryMegabytes;
    /** The folder holding {@value #SHARED_ARCHIVE}, or null. */
    private final Path sharedArchive;
    private final SandboxedProcess sandboxed;
    /** The warm compiler, or null: each compile is then a JVM of its own. */
    private final CompileServer compiler;

    /**
     * Runs the harness whose classes are in {@code harness}, in {@code sandbox}, with
     * {@code memoryMegabytes} of heap.
     */
    public StudentProcess(Sandbox sandbox, Path harness, int memoryMegabytes) {
        this(sandbox, harness, memoryMegabytes, null, null);
    }

    private StudentProcess(Sandbox sandbox, Path harness, int memoryMegabytes, Path sharedArchive,
            Path compilerFolder) {
        this.sandbox = sandbox;
        this.harness = harness;
        this.memoryMegabytes = memoryMegabytes;
        this.sharedArchive = sharedArchive;
        this.sandboxed = new SandboxedProcess(sandbox);
        this.compiler = compilerFolder == null ? null : new CompileServer(sandbox.forCompiler(), compilerFolder,
                this::startCompiler);
    }

    /**
     * The same process with a warm compiler of its own ({@link CompileServer}), which exchanges
     * sources and classes through {@code folder}, a new folder: for a cohort's job, which compiles
     * one submission after another. Every compile then runs in it, and no code runs in the JVM
     * that compiled it; {@link #close()} ends it.
     */
    public StudentProcess withWarmCompiler(Path folder) throws IOException {
        Files.createDirectory(folder);
        sandbox.forCompiler().share(folder, false);
        return new StudentProcess(sandbox, harness, memoryMegabytes, sharedArchive, folder);
    }

    /**
     * Compiles the {@code *.java} files of {@code sources} into {@code output}/classes, in the
     * sandbox; the student's files are reported as {@code sphereName} and {@code rendererName}.
     */
    public Compiled compile(Path sources, Path output, String sphereName, String rendererName, Duration timeLimit)
            throws IOException, InterruptedException {
        if (compiler != null) {
            return compileWarm(sources, output, sphereName, rendererName, timeLimit);
        }
        // Written in a folder of its own, whose class files are copied into output: what else the compile
        // left goes with its file system.
        Path written = Files.createDirectory(output.resolve("written"));
        sandbox.share(written, true);
        try (OutputDisk disk = sandbox.outputDisk(written)) {
            Run run = run(Request.of(List.of("compile", SOURCES, OUTPUT, sphereName, rendererName), timeLimit,
                    compilerJvm(false)).reading(sources, SOURCES).output(disk, OUTPUT));
            Compiled compiled = compiled(run, written, timeLimit);
            if (compiled.compiled()) {
                copyClasses(written.resolve(StudentHarness.CLASSES_FOLDER),
                        output.resolve(StudentHarness.CLASSES_FOLDER));
            }
            return compiled;
        } finally {
            WorkFolder.delete(written);
        }
    }

    /**
     * Compiles with the warm compiler, then copies the class files into {@code output}/classes, a
     * folder of the grader's: the JVMs that run the code are given that copy, read-only, never
     * the folder the compiler wrote. Only a compile within the output folder's caps is copied.
     */
    private Compiled compileWarm(Path sources, Path output, String sphereName, String rendererName,
            Duration timeLimit) throws IOException, InterruptedException {
        Path request = compiler.newRequest();
        try {
            try (var files = Files.list(sources)) {
                for (Path file : files.toList()) {
                    Files.copy(file, request.resolve(StudentHarness.SOURCES_FOLDER).resolve(file.getFileName()));
                }
            }
            Run run = compiler.compile(request, sphereName, rendererName, timeLimit);
            Path written = compiler.takeOutput(request);
            Compiled compiled = compiled(run, written, timeLimit);
            if (compiled.compiled()) {
                copyClasses(written.resolve(StudentHarness.CLASSES_FOLDER),
                        output.resolve(StudentHarness.CLASSES_FOLDER));
            }
            return compiled;
        } finally {
            compiler.done(request);   // what is left of it is deleted with the grade's work folder
        }
    }

    /**
     * Copies the folders and regular files under {@code from} to {@code to}, and nothing else:
     * no link is followed or copied.
     */
    private static void copyClasses(Path from, Path to) throws IOException {
        try (var files = Files.walk(from)) {
            for (Path file : files.toList()) {
                Path copy = to.resolve(from.relativize(file).toString());
                if (ChildOutput.isDirectory(file)) {
                    Files.createDirectories(copy);
                } else if (ChildOutput.isRegularFile(file)) {
                    Files.copy(file, copy, LinkOption.NOFOLLOW_LINKS);
                }
            }
        }
    }

    /** The compiler's JVM, for {@link CompileServer}: on the job's core, under the compiler's user, with its heap. */
    private SandboxedProcess.Started startCompiler(Sandbox compilerSandbox, Path folder, Duration timeLimit)
            throws IOException {
        Request request = Request.of(List.of(StudentHarness.COMPILE_SERVER, COMPILER), timeLimit, compilerJvm(true))
                .writing(folder, COMPILER);
        // Its processor time is bounded as that of the compiles one start serves, with a second each for
        // the JIT's and the collector's work between them.
        int cpuSeconds = ((int) Math.ceil(timeLimit.toMillis() / 1000.0) + 1) * CompileServer.COMPILES_PER_START;
        Launch launch = launch(request);
        return SandboxedProcess.start(compilerSandbox, launch.command(), launch.binds(), cpuSeconds, request.jvm(),
                false);
    }

    private int compilerHeap() {
        return Math.max(memoryMegabytes, COMPILER_HEAP_MEGABYTES);
    }

    /** The JVM that compiles: with the compiler's heap, on one core or not, mapping the shared archive. */
    private Jvm compilerJvm(boolean oneCore) {
        return new Jvm(compilerHeap(), oneCore, archiveOption());
    }

    /** The JVM that runs the student's code: with its heap, on one core, mapping the shared archive. */
    private Jvm studentJvm() {
        return new Jvm(memoryMegabytes, true, archiveOption());
    }

    /**
     * Compiles as {@link #compile} does, then, in the same JVM, renders the scenes as {@link #render}
     * does: one JVM start instead of two. Compiling may take {@code timeLimit}, and rendering as
     * long again from the moment the harness logs that it compiled; until then no code of the
     * student's has run, so that line can be trusted. Only for scenes that are not hidden, as the
     * compiled classes stay in the output folder the code can write.
     */
    public CompiledAndRendered compileAndRender(Path sources, Batch batch, Path output, String sphereName,
            String rendererName, Duration timeLimit) throws IOException, InterruptedException {
        try (OutputDisk disk = sandbox.outputDisk(output)) {
            Run run = run(Request.of(renderArguments(batch, List.of(StudentHarness.COMPILE_FIRST, SOURCES,
                    sphereName, rendererName)), timeLimit, studentJvm()).reading(sources, SOURCES)
                    .reading(batch.scenes(), SCENES).output(disk, OUTPUT)
                    .compilingFirst(output.resolve(StudentHarness.PROGRESS_FILE)));
            if (!run.compiledSeen()) {
                Compiled compiled = compiled(run, output, timeLimit);
                return new CompiledAndRendered(compiled.compiled()
                        ? new Compiled(List.of(), "the compiler stopped without logging that it had finished")
                        : compiled, null);
            }
            return new CompiledAndRendered(new Compiled(List.of(), null), rendered(run, output, batch, timeLimit));
        }
    }

    /**
     * The harness's arguments for rendering {@code batch}: "render", the probes if asked, {@code code}
     * (the classes, or the sources and the student's files' names), then the output folder, the size
     * and the scenes.
     */
    private static List<String> renderArguments(Batch batch, List<String> code) {
        List<String> arguments = new ArrayList<>(List.of("render"));
        if (batch.probes()) {
            arguments.add(StudentHarness.PROBES);
        }
        arguments.addAll(code);
        arguments.addAll(List.of(OUTPUT, Integer.toString(batch.width()), Integer.toString(batch.height())));
        batch.sceneFiles().forEach(name -> arguments.add(SCENES + "/" + name));
        return arguments;
    }

    /** What a run that compiled (or tried to) says about compiling. */
    private Compiled compiled(Run run, Path output, Duration timeLimit) throws IOException {
        if (run.limitReached() != null) {
            return new Compiled(List.of(), run.limitReached().words());
        }
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
     * Renders each scene of {@code batch} with the compiled classes in {@code classes}; {@code output}
     * is an empty folder for the child's images and logs. The run may take {@code timeLeft}, what is
     * left of the grade's {@code timeLimit}.
     */
    public Result render(Path classes, Batch batch, Path output, Duration timeLeft, Duration timeLimit)
            throws IOException, InterruptedException {
        try (OutputDisk disk = sandbox.outputDisk(output)) {
            Run run = run(Request.of(renderArguments(batch, List.of(CLASSES)), timeLeft, studentJvm())
                    .reading(classes, CLASSES).reading(batch.scenes(), SCENES).output(disk, OUTPUT)
                    .hidingScenes(batch.hidden()));
            return rendered(run, output, batch, timeLimit);
        }
    }

    private Result rendered(Run run, Path output, Batch batch, Duration timeLimit) throws IOException {
        List<String> sceneFiles = batch.sceneFiles();
        String progressText = ChildOutput.readText(output.resolve(StudentHarness.PROGRESS_FILE));
        List<Outcome> outcomes = new ArrayList<>();
        for (int i = 0; i < sceneFiles.size(); i++) {
            outcomes.add(progressText == null && run.finished() && run.exitStatus() == 0
                    ? new Outcome.Failed(NoImage.ENDED, "no image: the log of the run's progress is missing, "
                            + "unreadable or not a regular file (did the code remove, replace or chmod it?)")
                    : outcome(output, i, progressText == null ? List.of() : progressText.lines().toList(), run,
                            batch, timeLimit));
        }
        List<String> traces = new ArrayList<>();
        for (int i = 0; i < sceneFiles.size(); i++) {
            traces.add(ChildOutput.readText(output.resolve(i + StudentHarness.TRACE_SUFFIX)));
        }
        return new Result(run.limitReached() == null ? outcomes
                : outcomes.stream().map(outcome -> withLimit(outcome, run.limitReached())).toList(), run.outputTail(),
                traces, ChildOutput.readText(output.resolve(StudentHarness.PROBES_FILE), ChildOutput.PROBES_CAP));
    }

    /**
     * A scene's outcome when the run reached a total. Memory and the output folder's cap fail every
     * scene with the total's words (a process was killed, or the run stopped, so nothing of the run
     * counts); the process total follows the scene's own failure, on a line of its own (which a
     * hidden scene's report leaves out with the rest of the code's words), as the run went on.
     */
    private static Outcome withLimit(Outcome outcome, LimitReached limit) {
        if (limit.stoppedTheRun()) {
            return new Outcome.Failed(limit.kind(), limit.words());
        }
        return outcome instanceof Outcome.Failed failed
                ? new Outcome.Failed(failed.why(), failed.reason() + "\n" + limit.words(), true) : outcome;
    }

    /**
     * Writes the harness's class path into {@code folder}, as {@value #HARNESS_JAR}: the class
     * files of {@link StudentHarness#CLASSES} ({@link StudentHarness}, {@link StudentCompiler}
     * and those that call the student's methods), their nested classes, and
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
     * @return the process, as this one but with the archive and no warm compiler; or this one when the
     *     archive could not be made (Java then starts as it always does)
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
        Files.writeString(scenes.resolve("0.xml"), ARCHIVE_SCENE);
        sandbox.share(work, false);
        Path output = Files.createDirectory(work.resolve("output"));
        sandbox.share(output, true);
        try (OutputDisk disk = sandbox.outputDisk(output)) {
            // With the probes, so that the classes they load are in the archive too.
            List<String> code = List.of(StudentHarness.COMPILE_FIRST, SOURCES, "Sphere.java", "Renderer.java");
            Run run = run(Request.of(renderArguments(new Batch(scenes, List.of("0.xml"), 8, 6, true, false), code),
                    ARCHIVE_TIME_LIMIT, new Jvm(compilerHeap(), false,
                            List.of("-XX:ArchiveClassesAtExit=" + inside(output, OUTPUT) + "/" + SHARED_ARCHIVE)))
                    .reading(sources, SOURCES).reading(scenes, SCENES).output(disk, OUTPUT));
            Path archive = output.resolve(SHARED_ARCHIVE);
            // Without the image the run never reached ImageIO and the render: the archive would miss them.
            if (!run.finished() || !ChildOutput.isRegularFile(archive)
                    || !ChildOutput.isRegularFile(output.resolve("0.png"))) {
                return this;
            }
            Files.copy(archive, folder.resolve(SHARED_ARCHIVE));
        }
        Files.setPosixFilePermissions(folder.resolve(SHARED_ARCHIVE), PosixFilePermissions.fromString("r--r--r--"));
        return new StudentProcess(sandbox, harness, memoryMegabytes, folder, null);
    }

    /** The same process for another sandbox (a job's), with the same harness and archive, and no warm compiler. */
    public StudentProcess in(Sandbox other) {
        return new StudentProcess(other, harness, memoryMegabytes, sharedArchive, null);
    }

    /** Where {@code folder}, bound at {@code insideName}, is seen by the harness. */
    private String inside(Path folder, String insideName) {
        return sandbox.isConfined() ? insideName : folder.toString();
    }

    /** Kills the sandbox that is running, if one is, and the warm compiler (on Ctrl-C or SIGTERM). */
    public void stop() {
        sandboxed.stop();
        if (compiler != null) {
            compiler.stop();
        }
    }

    /** Ends the warm compiler, if there is one; a later compile starts it again. */
    @Override
    public void close() {
        if (compiler != null) {
            compiler.close();
        }
    }

    /** The JVM option that maps the class data sharing archive, when there is one. */
    private List<String> archiveOption() {
        return sharedArchive == null ? List.of()
                : List.of("-XX:SharedArchiveFile=" + inside(sharedArchive, ARCHIVE) + "/" + SHARED_ARCHIVE);
    }

    /** The JVM's command line and the folders bound in: the harness's jar and archive with the request's own. */
    private record Launch(List<String> command, List<Bind> binds) {
    }

    /** Runs the harness as {@code request} says, in the sandbox, with the harness's jar and archive bound in. */
    private Run run(Request request) throws IOException, InterruptedException {
        Launch launch = launch(request);
        return sandboxed.run(launch.command(), request.withBinds(launch.binds()));
    }

    private Launch launch(Request request) {
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + request.jvm().heapMegabytes() + "m",
                // A small first heap: the default (a 64th of the machine's memory) is fresh pages that fault in
                // as the render allocates, which costs the render processor time.
                "-Xms" + Math.min(FIRST_HEAP_MEGABYTES, request.jvm().heapMegabytes()) + "m",
                "-XX:MaxDirectMemorySize=32m",
                "-XX:CompressedClassSpaceSize=64m",
                "-XX:ReservedCodeCacheSize=64m",
                "-XX:+UseSerialGC",               // one GC thread: the student's code is single-threaded
                "-XX:TieredStopAtLevel=1",        // quick start; small renders are over before C2 pays
                "-XX:CICompilerCount=1",          // one JIT thread: the student code has one core; a second competes
                "-XX:-UsePerfData",               // no shared-memory file in /tmp (there is no /tmp)
                "-Djava.awt.headless=true",
                "-Djava.io.tmpdir=" + (sandbox.isConfined() ? OUTPUT : System.getProperty("java.io.tmpdir")),
                "-cp", inside(harness, HARNESS) + "/" + HARNESS_JAR));
        command.addAll(request.jvm().options());
        command.add(StudentHarness.class.getName());
        command.addAll(sandbox.isConfined() ? request.harnessArguments()
                : SandboxedProcess.unconfinedArguments(request.harnessArguments(), request.binds()));
        List<Bind> binds = new ArrayList<>(request.binds());
        binds.add(new Bind(harness, HARNESS, false));
        if (sharedArchive != null) {
            binds.add(new Bind(sharedArchive, ARCHIVE, false));
        }
        return new Launch(command, binds);
    }

    private static Outcome outcome(Path output, int index, List<String> progress, Run run, Batch batch,
            Duration timeLimit) throws IOException {
        Path image = output.resolve(index + ".png");
        String error = ChildOutput.readText(output.resolve(index + ".error"));
        if (error != null) {
            return new Outcome.Failed(NoImage.THREW, "the code threw " + error);
        }
        if (progress.contains("end " + index) && ChildOutput.isRegularFile(image)) {
            try {
                return new Outcome.Rendered(ChildOutput.readPng(image, batch.width(), batch.height()));
            } catch (ChildOutput.Unusable e) {
                return new Outcome.Failed(NoImage.ENDED,
                        "the image written for this scene is unusable: " + e.getMessage());
            }
        }
        if (!run.finished()) {
            if (!progress.contains("start " + index) && index > 0) {
                return new Outcome.Failed(NoImage.TIME_LIMIT,
                        "not rendered: the time limit was reached at an earlier scene");
            }
            return new Outcome.Failed(NoImage.TIME_LIMIT, "no image within the time limit of " + describe(timeLimit)
                    + " (an infinite loop?); the program was stopped");
        }
        if (!progress.contains("start " + index)) {
            return new Outcome.Failed(NoImage.ENDED, "not rendered: the run stopped at an earlier scene");
        }
        int exitStatus = run.exitStatus();
        return new Outcome.Failed(NoImage.ENDED, "the program ended while rendering this scene, with exit status "
                + exitStatus
                + (exitStatus == 0 ? " (does the code call System.exit?)" : " (System.exit, or the JVM crashed)"));
    }

    static String describe(Duration duration) {
        long millis = duration.toMillis();
        return millis % 1000 == 0 ? millis / 1000 + " s" : millis / 1000.0 + " s";
    }
}
