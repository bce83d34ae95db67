package gfx.tick1.command.shared.grader.sandbox;

import static gfx.tick1.command.shared.grader.sandbox.HarnessJvm.CLASSES;
import static gfx.tick1.command.shared.grader.sandbox.HarnessJvm.HARNESS_JAR;
import static gfx.tick1.command.shared.grader.sandbox.HarnessJvm.OUTPUT;
import static gfx.tick1.command.shared.grader.sandbox.HarnessJvm.SCENES;
import static gfx.tick1.command.shared.grader.sandbox.HarnessJvm.SHARED_ARCHIVE;
import static gfx.tick1.command.shared.grader.sandbox.HarnessJvm.SOURCES;

import gfx.tick1.command.shared.grader.harness.StudentCompiler;
import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Request;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Run;
import gfx.tick1.command.shared.kit.StarterKit;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;

/**
 * Runs {@link StudentHarness} in a JVM of its own inside the {@link Sandbox} ({@link HarnessJvm}), with a
 * heap limit and a time limit, so that an infinite loop, a crash, or a call to System.exit in the student's
 * code is reported and never inherited, and so that the student's code can do nothing outside it. On the
 * time limit the sandbox is killed, and with it everything the student's code started.
 */
public final class StudentProcess implements AutoCloseable {

    /**
     * The scene the shared archive's run renders: one the starter kit's SceneLoader accepts (every
     * colour given), so that the DOM parser, the image classes and ImageIO's PNG writer are archived
     * along with javac.
     */
    private static final String ARCHIVE_SCENE = "<scene><ambient-light colour=\"#202020\"/>"
            + "<point-light x=\"1\" y=\"1\" colour=\"#FFFFFF\"/><sphere z=\"4\" colour=\"#FF0000\"/></scene>\n";
    /** How long making the shared archive may take. */
    private static final Duration ARCHIVE_TIME_LIMIT = Duration.ofSeconds(60);
    /**
     * A folder holding an archive that {@link #withSharedArchive} made, which every confined run then maps: for the
     * tests, which grade hundreds of times in one run and make one archive for them all. A grade alone would spend
     * more making one than mapping it saves.
     */
    public static final String KEPT_ARCHIVE_PROPERTY = "tick1.grade.harnessArchive";
    /** The earliest time a harness's jar is given ({@link #writeHarness}). */
    private static final Instant HARNESS_EPOCH = Instant.parse("2000-01-01T00:00:00Z");
    /**
     * How many seconds after {@link #HARNESS_EPOCH} a harness's jar may be given: twenty years, which keeps every
     * such time in the past and within what a zip entry's date and a 32-bit time in seconds can hold.
     */
    private static final long HARNESS_TIMES = 20L * 365 * 24 * 60 * 60;

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
     * {@code width} x {@code height}, of the public {@code kind} (the harness then also runs the
     * probes) or the organiser's hidden one (under the stricter seccomp filter).
     */
    public record Batch(Path scenes, List<String> sceneFiles, int width, int height, SceneBatch kind) {
    }

    private final HarnessJvm jvm;
    private final SandboxedProcess sandboxed;
    /** The warm compiler, or null: each compile is then a JVM of its own. */
    private final CompileServer compiler;

    /**
     * Runs the harness whose classes are in {@code harness}, in {@code sandbox}, with
     * {@code memoryMegabytes} of heap.
     */
    public StudentProcess(Sandbox sandbox, Path harness, int memoryMegabytes) {
        this(new HarnessJvm(sandbox, harness, memoryMegabytes, keptArchive(sandbox)), null);
    }

    /**
     * The folder named by {@link #KEPT_ARCHIVE_PROPERTY}, for a confined run; otherwise, or when the property is
     * blank, null. Outside a sandbox each grade's jar is at a path of its own, which an archive made for another
     * jar's never fits.
     */
    private static Path keptArchive(Sandbox sandbox) {
        String folder = System.getProperty(KEPT_ARCHIVE_PROPERTY, "");
        return folder.isBlank() || !sandbox.isConfined() ? null : Path.of(folder);
    }

    private StudentProcess(HarnessJvm jvm, Path compilerFolder) {
        this.jvm = jvm;
        this.sandboxed = new SandboxedProcess(jvm.sandbox());
        this.compiler = compilerFolder == null ? null
                : new CompileServer(jvm.sandbox().forCompiler(), compilerFolder, jvm::startCompiler);
    }

    /**
     * The same process with a warm compiler of its own ({@link CompileServer}), which exchanges
     * sources and classes through {@code folder}, a new folder: for a cohort's job, which compiles
     * one submission after another. Every compile then runs in it, and no code runs in the JVM
     * that compiled it; {@link #close()} ends it.
     */
    public StudentProcess withWarmCompiler(Path folder) throws IOException {
        Files.createDirectory(folder);
        jvm.sandbox().forCompiler().share(folder);
        return new StudentProcess(jvm, folder);
    }

    /**
     * Writes {@code sphere} and {@code renderer} as Sphere.java and Renderer.java into a new folder
     * {@code work}/sources, with the starter kit's other classes beside them: the sources {@link #compile} takes.
     */
    public static Path writeSources(Path work, String sphere, String renderer) throws IOException {
        Path sources = Files.createDirectory(work.resolve("sources"));
        Files.writeString(sources.resolve("Sphere.java"), sphere, StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("Renderer.java"), renderer, StandardCharsets.UTF_8);
        for (String given : StarterKit.GIVEN_CLASSES) {
            Files.writeString(sources.resolve(given + ".java"), StarterKit.source(given), StandardCharsets.UTF_8);
        }
        return sources;
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
        jvm.sandbox().shareWritable(written);
        try (OutputDisk disk = jvm.sandbox().outputDisk(written)) {
            Run run = run(Request.of(List.of("compile", SOURCES, OUTPUT, sphereName, rendererName), timeLimit,
                    jvm.compiler()).reading(sources, SOURCES).output(disk, OUTPUT));
            return copiedIfCompiled(run, written, output, timeLimit);
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
            return copiedIfCompiled(run, compiler.takeOutput(request), output, timeLimit);
        } finally {
            compiler.done(request);   // what is left of it is deleted with the grade's work folder
        }
    }

    /** What the compile that wrote in {@code written} gave; if it compiled, its classes copied into {@code output}. */
    private Compiled copiedIfCompiled(Run run, Path written, Path output, Duration timeLimit) throws IOException {
        Compiled compiled = HarnessOutput.compiled(run, written, timeLimit, jvm.compilerHeap());
        if (compiled.compiled()) {
            ChildOutput.copy(written.resolve(StudentHarness.CLASSES_FOLDER),
                    output.resolve(StudentHarness.CLASSES_FOLDER));
        }
        return compiled;
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
        try (OutputDisk disk = jvm.sandbox().outputDisk(output)) {
            Run run = run(Request.of(renderArguments(batch, List.of(StudentHarness.COMPILE_FIRST, SOURCES,
                    sphereName, rendererName)), timeLimit, jvm.student()).reading(sources, SOURCES)
                    .reading(batch.scenes(), SCENES).output(disk, OUTPUT)
                    .compilingFirst(output.resolve(StudentHarness.PROGRESS_FILE)));
            if (!run.compiledSeen()) {
                Compiled compiled = HarnessOutput.compiled(run, output, timeLimit, jvm.compilerHeap());
                return new CompiledAndRendered(compiled.compiled()
                        ? new Compiled(List.of(), "the compiler stopped without logging that it had finished")
                        : compiled, null);
            }
            return new CompiledAndRendered(new Compiled(List.of(), null),
                    HarnessOutput.rendered(run, output, batch, timeLimit));
        }
    }

    /**
     * The harness's arguments for rendering {@code batch}: "render", the probes for a public batch,
     * {@code code} (the classes, or the sources and the student's files' names), then the output
     * folder, the size and the scenes.
     */
    private static List<String> renderArguments(Batch batch, List<String> code) {
        List<String> arguments = new ArrayList<>(List.of("render"));
        if (batch.kind() == SceneBatch.PUBLIC) {
            arguments.add(StudentHarness.PROBES);
        }
        arguments.addAll(code);
        arguments.addAll(List.of(OUTPUT, Integer.toString(batch.width()), Integer.toString(batch.height())));
        batch.sceneFiles().forEach(name -> arguments.add(SCENES + "/" + name));
        return arguments;
    }

    /**
     * Renders each scene of {@code batch} with the compiled classes in {@code classes}; {@code output}
     * is an empty folder for the child's images and logs. The run may take {@code timeLeft}, what is
     * left of the grade's {@code timeLimit}.
     */
    public Result render(Path classes, Batch batch, Path output, Duration timeLeft, Duration timeLimit)
            throws IOException, InterruptedException {
        try (OutputDisk disk = jvm.sandbox().outputDisk(output)) {
            Run run = run(Request.of(renderArguments(batch, List.of(CLASSES)), timeLeft, jvm.student())
                    .reading(classes, CLASSES).reading(batch.scenes(), SCENES).output(disk, OUTPUT)
                    .rendering(batch.kind()));
            return HarnessOutput.rendered(run, output, batch, timeLimit);
        }
    }

    /**
     * Writes the harness's class path into {@code folder}, as {@value HarnessJvm#HARNESS_JAR}: the class
     * files of {@link StudentHarness#CLASSES} ({@link StudentHarness}, {@link StudentCompiler}
     * and those that call the student's methods), their nested classes, and
     * nothing else of this program (no reference renderer, no scenes, no images for
     * the student's code to use). A jar, not a folder, as Java's class data sharing needs one.
     */
    public static void writeHarness(Path folder) throws IOException {
        Map<String, byte[]> classes = new LinkedHashMap<>();
        int hash = 0;
        for (Class<?> top : StudentHarness.CLASSES) {
            for (Class<?> type : top.getNestMembers()) {
                String file = type.getName().replace('.', '/') + ".class";
                try (InputStream in = type.getResourceAsStream("/" + file)) {
                    if (in == null) {
                        throw new IOException("cannot find this program's own class " + file);
                    }
                    byte[] bytes = in.readAllBytes();
                    classes.put(file, bytes);
                    hash = 31 * (31 * hash + file.hashCode()) + Arrays.hashCode(bytes);
                }
            }
        }
        // Java checks a mapped archive's jar by its size and its time in seconds alone. A time that follows from
        // the classes (a hash of their names and bytes) makes every jar of the same classes the same file to it,
        // grade after grade, so that one archive serves them all (the tests', KEPT_ARCHIVE_PROPERTY), and a jar of
        // other classes, all but surely, another file, whose stale archive Java then refuses.
        FileTime time = FileTime.from(HARNESS_EPOCH.plusSeconds(Integer.toUnsignedLong(hash) % HARNESS_TIMES));
        Path jarFile = folder.resolve(HARNESS_JAR);
        try (JarOutputStream jar = new JarOutputStream(Files.newOutputStream(jarFile))) {
            for (Map.Entry<String, byte[]> file : classes.entrySet()) {
                JarEntry entry = new JarEntry(file.getKey());
                entry.setLastModifiedTime(time);
                jar.putNextEntry(entry);
                jar.write(file.getValue());
                jar.closeEntry();
            }
        }
        Files.setLastModifiedTime(jarFile, time);
    }

    /**
     * Makes a class data sharing archive for the harness in {@code folder}: a run of the harness,
     * in the sandbox, that compiles the untouched starter kit and renders a tiny scene with it,
     * and writes every class it loaded (javac's included) into {@value HarnessJvm#SHARED_ARCHIVE}. A JVM
     * that maps the archive starts and compiles quicker. Only the starter kit runs, so the archive
     * holds nothing of any student's; the sandbox is used only so that the paths are the ones
     * every later run sees. {@code work} is an empty folder for the run.
     *
     * @return the process, as this one but with the archive and no warm compiler; or this one when the
     *     archive could not be made (Java then starts as it always does)
     */
    public StudentProcess withSharedArchive(Path folder, Path work) throws IOException, InterruptedException {
        Path sources = writeSources(work, StarterKit.source("Sphere"), StarterKit.source("Renderer"));
        Path scenes = Files.createDirectory(work.resolve("scenes"));
        Files.writeString(scenes.resolve("0.xml"), ARCHIVE_SCENE);
        Sandbox sandbox = jvm.sandbox();
        sandbox.share(work);
        Path output = Files.createDirectory(work.resolve("output"));
        sandbox.shareWritable(output);
        try (OutputDisk disk = sandbox.outputDisk(output)) {
            // With the probes, so that the classes they load are in the archive too.
            List<String> code = List.of(StudentHarness.COMPILE_FIRST, SOURCES, "Sphere.java", "Renderer.java");
            Batch batch = new Batch(scenes, List.of("0.xml"), 8, 6, SceneBatch.PUBLIC);
            Run run = run(Request.of(renderArguments(batch, code), ARCHIVE_TIME_LIMIT, jvm.archiving(output))
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
        return new StudentProcess(jvm.withArchive(folder), null);
    }

    /** The same process for another sandbox (a job's), with the same harness and archive, and no warm compiler. */
    public StudentProcess in(Sandbox other) {
        return new StudentProcess(jvm.in(other), null);
    }

    /** Runs the harness as {@code request} says, in the sandbox, with the harness's jar and archive bound in. */
    private Run run(Request request) throws IOException, InterruptedException {
        return sandboxed.run(jvm.command(request), request.withBinds(jvm.binds(request)));
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
}
