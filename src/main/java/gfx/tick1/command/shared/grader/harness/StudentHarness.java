package gfx.tick1.command.shared.grader.harness;

import java.awt.image.BufferedImage;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.lang.reflect.InvocationTargetException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import javax.imageio.ImageIO;

/**
 * The program {@code grade} runs in a JVM of its own, inside the sandbox, to compile and to run a
 * student's code. It needs only the JDK and {@link StudentCompiler}: its class path holds these
 * classes and nothing else of this program. Two commands:
 *
 * <ul>
 *   <li>{@code compile SOURCES OUTPUT SPHERE-NAME RENDERER-NAME}: compiles every {@code *.java}
 *       in SOURCES ({@code Sphere.java} and {@code Renderer.java} reported under the names given,
 *       the others as starter code) into {@code OUTPUT/classes}; exits 0, or writes the errors,
 *       separated by NUL characters, to {@code OUTPUT/errors} and exits 1.
 *   <li>{@code compile-server FOLDER}: the warm compiler. For each line {@code N} it reads on
 *       standard input, compiles {@code FOLDER/N/sources} into {@code FOLDER/N/output} as
 *       {@code compile} does, with the two names given in {@code FOLDER/N/names} (separated by a
 *       NUL character), then prints {@code compiled N STATUS} (the status {@code compile} exits
 *       with). javac runs with {@code -proc:none}, so no code of the student's ever runs in it,
 *       and the JIT's work on javac serves every compile after the first.
 *   <li>{@code render --compile SOURCES SPHERE-NAME RENDERER-NAME OUTPUT WIDTH HEIGHT SCENE...}:
 *       compiles as {@code compile} does, logs "compiled" in {@code OUTPUT/progress} before any
 *       code of the student's is loaded, and renders as {@code render} does with
 *       {@code OUTPUT/classes}: one JVM start for both.
 *   <li>{@code render CLASSES OUTPUT WIDTH HEIGHT SCENE...}: for each scene, loads it with the
 *       starter code's {@code SceneLoader}, renders it with the student's {@code Renderer} and
 *       writes {@code OUTPUT/<index>.png}, or {@code OUTPUT/<index>.error} with what went wrong.
 *       {@code OUTPUT/progress} logs "start i" and "end i" lines, so that whoever stops this
 *       process (on a time limit) or sees it die (System.exit, a crash) knows which scene it was on.
 *       After each image is written, a grid of its pixels is traced again through the student's
 *       own methods into {@code OUTPUT/<index>.trace} ({@link SampleTrace}).
 *   <li>{@code render --probes ...}: as either form of {@code render}, and after the last scene
 *       calls the student's two methods on the fixed inputs of {@link BehaviourInputs}, logging what
 *       they return in {@code OUTPUT/probes} ({@link AnswerLog}).
 * </ul>
 *
 * <p>Everything this process writes is written while the student's code runs in it, so
 * {@code grade} trusts none of it (the grader reads it through the sandbox's ChildOutput).
 */
public final class StudentHarness {

    public static final String PROGRESS_FILE = "progress";
    public static final String ERRORS_FILE = "errors";
    public static final String CLASSES_FOLDER = "classes";
    /** Exit status of {@code compile} when the code does not compile. */
    public static final int DOES_NOT_COMPILE = 3;
    /** The option of {@code render} that compiles first. */
    public static final String COMPILE_FIRST = "--compile";
    /** The command of the warm compiler. */
    public static final String COMPILE_SERVER = "compile-server";
    /** The file of a warm compile's request that names the two files, separated by a NUL character. */
    public static final String NAMES_FILE = "names";
    /** The request's folders for the sources and for what compiling gave. */
    public static final String SOURCES_FOLDER = "sources", OUTPUT_FOLDER = "output";
    /** The line of the progress log that says compiling is over and the student's code may run. */
    public static final String COMPILED = "compiled";
    /** The option of {@code render}, before any other, that calls the two methods on fixed inputs after the scenes. */
    public static final String PROBES = "--probes";
    /** The log of their answers, in the output folder. */
    public static final String PROBES_FILE = AnswerLog.ANSWERS_FILE;
    /** The file of a scene's traced samples, beside its image: {@code <index>.trace}. */
    public static final String TRACE_SUFFIX = ".trace";

    /**
     * The system property that a run outside the sandbox sets to the process id of the tick1 that starts it: the
     * harness then stops the processes the student's code started when it ends, and ends when that tick1 is gone
     * (its parent, unless tick1 died before the harness could look). In the sandbox its PID namespace and bwrap's
     * --die-with-parent do both, and there is no /proc to do them by.
     */
    public static final String GRADER_PID = "tick1.graderPid";
    /** The exit status of a harness whose parent is gone: nobody reads it. */
    private static final int PARENT_GONE = 143;

    /** The classes of the harness's jar: these and their nested classes are all of tick1 the child sees. */
    public static final List<Class<?>> CLASSES = List.of(StudentHarness.class, StudentCompiler.class,
            StarterApi.class, BehaviourInputs.class, AnswerLog.class, SampleTrace.class, Bounded.class);

    /** Whether {@code render} calls the two methods on fixed inputs after the scenes ({@link #PROBES}). */
    private enum Probes { ASKED, NONE }

    private StudentHarness() {
    }

    public static void main(String[] arguments) throws Exception {
        if (unconfined()) {
            // However this process ends (its end, the student's System.exit, a stop), what the student's code
            // started and left running ends with it, and it ends with tick1: outside the sandbox nothing else would.
            Runtime.getRuntime().addShutdownHook(new Thread(StudentHarness::stopStartedProcesses, "stop-started"));
            long grader = Long.parseLong(System.getProperty(GRADER_PID));
            ProcessHandle.current().parent().filter(parent -> parent.pid() == grader)
                    .map(ProcessHandle::onExit).orElse(CompletableFuture.completedFuture(null)).thenRun(() -> {
                        stopStartedProcesses();
                        Runtime.getRuntime().halt(PARENT_GONE);
                    });
        }
        Probes probes = arguments.length > 1 && arguments[1].equals(PROBES) ? Probes.ASKED : Probes.NONE;
        String[] args = probes == Probes.ASKED ? dropSecond(arguments) : arguments;
        if (args[0].equals(COMPILE_SERVER)) {
            serveCompiles(Path.of(args[1]));
            return;
        }
        if (args[0].equals("compile")) {
            System.exit(compile(Path.of(args[1]), Path.of(args[2]), args[3], args[4]));
        }
        if (args[1].equals(COMPILE_FIRST)) {
            Path output = Path.of(args[5]);
            int status = compile(Path.of(args[2]), output, args[3], args[4]);
            if (status != 0) {
                System.exit(status);
            }
            log(output.resolve(PROGRESS_FILE), COMPILED);
            render(output.resolve(CLASSES_FOLDER), output, Integer.parseInt(args[6]), Integer.parseInt(args[7]),
                    List.of(args).subList(8, args.length), probes);
            return;
        }
        render(Path.of(args[1]), Path.of(args[2]), Integer.parseInt(args[3]), Integer.parseInt(args[4]),
                List.of(args).subList(5, args.length), probes);
    }

    private static String[] dropSecond(String[] args) {
        List<String> rest = new ArrayList<>(List.of(args));
        rest.remove(1);
        return rest.toArray(new String[0]);
    }

    /** The warm compiler's loop: one request a line, until standard input ends. */
    private static void serveCompiles(Path folder) throws Exception {
        BufferedReader requests = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        for (String request; (request = requests.readLine()) != null; ) {
            if (!request.matches("[0-9]{1,9}")) {
                throw new IllegalArgumentException("not a request number: " + request);
            }
            Path asked = folder.resolve(request);
            String[] names = Files.readString(asked.resolve(NAMES_FILE), StandardCharsets.UTF_8).split("\0", 2);
            int status = compile(asked.resolve(SOURCES_FOLDER), asked.resolve(OUTPUT_FOLDER), names[0], names[1]);
            System.out.println(COMPILED + " " + request + " " + status);
            System.out.flush();
        }
    }

    private static int compile(Path sources, Path output, String sphereName, String rendererName) throws Exception {
        List<StudentCompiler.Source> files = new ArrayList<>();
        try (var listing = Files.list(sources)) {
            for (Path file : listing.sorted().toList()) {
                String className = file.getFileName().toString().replaceAll("\\.java$", "");
                String name = switch (className) {
                    case "Sphere" -> sphereName;
                    case "Renderer" -> rendererName;
                    default -> "starter code " + className + ".java";
                };
                files.add(new StudentCompiler.Source(className, name, Files.readString(file, StandardCharsets.UTF_8)));
            }
        }
        StudentCompiler.Result result = new StudentCompiler().compile(files);
        if (!result.compiled()) {
            Files.writeString(output.resolve(ERRORS_FILE), String.join("\0", result.errors()), StandardCharsets.UTF_8);
            return DOES_NOT_COMPILE;
        }
        result.writeClasses(output.resolve(CLASSES_FOLDER));
        return 0;
    }

    private static void render(Path classes, Path output, int width, int height, List<String> scenes,
            Probes probes) throws IOException {
        Path progress = output.resolve(PROGRESS_FILE);
        try (URLClassLoader student = new URLClassLoader(new URL[] {classes.toUri().toURL()},
                ClassLoader.getPlatformClassLoader())) {
            for (int index = 0; index < scenes.size(); index++) {
                log(progress, "start " + index);
                try {
                    BufferedImage image = render(student, scenes.get(index), width, height);
                    writePng(image, output.resolve(index + ".png"));
                    trace(student, scenes.get(index), width, height, output.resolve(index + TRACE_SUFFIX));
                } catch (Throwable failure) { // the student's code may throw anything, errors included
                    writeFailure(output.resolve(index + ".error"), failure);
                }
                log(progress, "end " + index);
            }
            if (probes == Probes.ASKED) {
                AnswerLog.write(student, output.resolve(PROBES_FILE));
            }
        }
        // Student code may have left threads (and, outside the sandbox, processes) running; the results are
        // written, so stop here.
        if (unconfined()) {
            stopStartedProcesses();
        }
        Runtime.getRuntime().halt(0);
    }

    /**
     * Writes {@code image} as a PNG through a stream: ImageIO writing to a File starts a thread of its own (Java2D's
     * Disposer), which a run whose threads the code has brought to the limit of processes and threads cannot start,
     * and the image would be lost for the harness's want of a thread.
     */
    private static void writePng(BufferedImage image, Path file) throws IOException {
        ImageIO.setUseCache(false); // in memory, not in a cache file
        try (OutputStream out = Files.newOutputStream(file)) {
            ImageIO.write(image, "png", out);
        }
    }

    private static boolean unconfined() {
        return System.getProperty(GRADER_PID) != null;
    }

    /** Kills every process that this one started, and theirs, that still runs. */
    private static void stopStartedProcesses() {
        try {
            ProcessHandle.current().descendants().forEach(ProcessHandle::destroyForcibly);
        } catch (RuntimeException e) {
            // No way to list them here (no /proc): nothing more this process can do.
        }
    }

    /** Traces the samples of a scene whose image is written; without the starter's API, none. */
    private static void trace(ClassLoader student, String scenePath, int width, int height, Path file)
            throws IOException {
        try {
            StarterApi api = new StarterApi(student);
            Class<?> loaderClass = student.loadClass("gfx.tick1.SceneLoader");
            Object scene = loaderClass.getMethod("getScene")
                    .invoke(loaderClass.getConstructor(String.class).newInstance(scenePath));
            SampleTrace.trace(api, scene, width, height, file);
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            // No trace file: the grader cannot check the image against the methods, and says so.
        }
    }

    private static BufferedImage render(ClassLoader student, String scenePath, int width, int height)
            throws ReflectiveOperationException {
        try {
            Class<?> loaderClass = student.loadClass("gfx.tick1.SceneLoader");
            Object loader = loaderClass.getConstructor(String.class).newInstance(scenePath);
            Object scene = loaderClass.getMethod("getScene").invoke(loader);
            Class<?> sceneClass = student.loadClass("gfx.tick1.Scene");
            Class<?> rendererClass = student.loadClass("gfx.tick1.Renderer");
            Object renderer = rendererClass.getConstructor(int.class, int.class).newInstance(width, height);
            Object image = rendererClass.getMethod("render", sceneClass).invoke(renderer, scene);
            if (!(image instanceof BufferedImage picture)) {
                throw new IllegalStateException("Renderer.render returned " + image + ", not an image");
            }
            if (picture.getWidth() != width || picture.getHeight() != height) {
                throw new IllegalStateException("Renderer.render returned a " + picture.getWidth() + " x "
                        + picture.getHeight() + " image, expected " + width + " x " + height);
            }
            return picture;
        } catch (InvocationTargetException e) {
            throw new StudentCodeException(e.getCause());
        }
    }

    /**
     * Writes what {@code failure} was into {@code file}: a message the code made may hold a lone surrogate, which
     * {@link String#getBytes} writes as '?' where {@link Files#writeString} would throw; and the code's
     * exception may throw from its own toString or getStackTrace, which leaves only its class's name.
     */
    static void writeFailure(Path file, Throwable failure) throws IOException {
        Throwable cause = failure instanceof StudentCodeException ? failure.getCause() : failure;
        String text;
        try {
            text = describe(cause);
        } catch (Throwable thrown) { // the exception's own methods are the student's code
            text = cause.getClass().getName();
        }
        Files.write(file, text.getBytes(StandardCharsets.UTF_8));
    }

    /**
     * The exception, then its stack frames in the student's and the starter's code: the classes
     * of package gfx.tick1 itself, not of this harness in gfx.tick1.command.shared.grader.
     */
    private static String describe(Throwable cause) {
        List<String> lines = new ArrayList<>();
        lines.add(reachedTheMemoryLimit(cause) ? cause + " (the memory limit was reached)" : cause.toString());
        for (StackTraceElement frame : cause.getStackTrace()) {
            if (frame.getClassName().matches("gfx\\.tick1\\.[^.]+") && lines.size() <= 8) {
                lines.add("at " + frame);
            }
        }
        return String.join("\n", lines);
    }

    /**
     * An OutOfMemoryError of the heap or the metaspace, the limits the grader sets (its messages are HotSpot's,
     * "Java heap space", "GC overhead limit exceeded", "Metaspace", "Compressed class space"); not one such as
     * "unable to create native thread", which is the limit on threads or the machine's own memory.
     */
    private static boolean reachedTheMemoryLimit(Throwable cause) {
        String message = cause instanceof OutOfMemoryError ? cause.getMessage() : null;
        return message != null && (message.startsWith("Java heap space") || message.startsWith("GC overhead limit")
                || message.startsWith("Metaspace") || message.startsWith("Compressed class space"));
    }

    private static void log(Path progress, String line) throws IOException {
        Files.writeString(progress, line + "\n", StandardCharsets.UTF_8, StandardOpenOption.CREATE,
                StandardOpenOption.APPEND);
    }

    /** An exception thrown by the student's (or the starter's) code, not by this harness. */
    private static final class StudentCodeException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        StudentCodeException(Throwable cause) {
            super(cause);
        }
    }
}
