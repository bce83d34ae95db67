package gfx.tick1.command.shared.grader.sandbox;

import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.sandbox.Sandbox.Bind;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Jvm;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Request;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * The harness's JVM in {@code sandbox}: the same Java as this program, its heap (the student's code's,
 * {@code memoryMegabytes}, or the compiler's), its command line, and the folders every run has bound in
 * besides its own: the harness's jar in {@code harness}, its only class path, and the class data sharing
 * archive in {@code sharedArchive} (or null for none).
 */
record HarnessJvm(Sandbox sandbox, Path harness, int memoryMegabytes, Path sharedArchive) {

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

    /** The same JVM in another sandbox (a job's). */
    HarnessJvm in(Sandbox other) {
        return new HarnessJvm(other, harness, memoryMegabytes, sharedArchive);
    }

    /** The same JVM mapping the archive in {@code folder}. */
    HarnessJvm withArchive(Path folder) {
        return new HarnessJvm(sandbox, harness, memoryMegabytes, folder);
    }

    /** The compiler's heap: the student's code's, or what javac needs where that is less. */
    int compilerHeap() {
        return Math.max(memoryMegabytes, COMPILER_HEAP_MEGABYTES);
    }

    /** The JVM that compiles in a run of its own: with the compiler's heap, on every core, mapping the archive. */
    Jvm compiler() {
        return new Jvm(compilerHeap(), false, archiveOption());
    }

    /** The JVM that runs the student's code: with its heap, on one core, mapping the archive. */
    Jvm student() {
        return new Jvm(memoryMegabytes, true, archiveOption());
    }

    /** The JVM that makes the archive in {@code output}: with the compiler's heap, on every core. */
    Jvm archiving(Path output) {
        return new Jvm(compilerHeap(), false,
                List.of("-XX:ArchiveClassesAtExit=" + inside(output, OUTPUT) + "/" + SHARED_ARCHIVE));
    }

    /**
     * The warm compiler's JVM, for {@link CompileServer}: in {@code compilerSandbox}, on the job's core,
     * with the compiler's heap, writing in {@code folder}, for compiles of at most {@code timeLimit}.
     */
    SandboxedProcess.Started startCompiler(Sandbox compilerSandbox, Path folder, Duration timeLimit)
            throws IOException {
        Request request = Request.of(List.of(StudentHarness.COMPILE_SERVER, COMPILER), timeLimit,
                new Jvm(compilerHeap(), true, archiveOption())).writing(folder, COMPILER);
        // Its processor time is bounded as that of the compiles one start serves, with a second each for
        // the JIT's and the collector's work between them.
        int cpuSeconds = ((int) Math.ceil(timeLimit.toMillis() / 1000.0) + 1) * CompileServer.COMPILES_PER_START;
        return SandboxedProcess.start(compilerSandbox, command(request), binds(request), cpuSeconds, request.jvm(),
                request.batch());
    }

    /** Where {@code folder}, bound at {@code insideName}, is seen by the harness. */
    private String inside(Path folder, String insideName) {
        return sandbox.isConfined() ? insideName : folder.toString();
    }

    /**
     * The JVM options that map the class data sharing archive, when there is one; silently, as a JVM that cannot
     * map it starts without it, and a newer Java would say so among what the student's code printed.
     */
    private List<String> archiveOption() {
        return sharedArchive == null ? List.of()
                : List.of("-XX:SharedArchiveFile=" + inside(sharedArchive, ARCHIVE) + "/" + SHARED_ARCHIVE,
                        "-Xlog:cds=off", "-Xlog:cds+dynamic=off");
    }

    /** The JVM's command line for {@code request}, as outside the sandbox. */
    List<String> command(Request request) {
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + request.jvm().heapMegabytes() + "m",
                // A small first heap: the default (a 64th of the machine's memory) is fresh pages that fault in
                // as the render allocates, which costs the render processor time (docs/benchmark.md, the levers).
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
        if (!sandbox.isConfined()) {
            command.add("-D" + StudentHarness.GRADER_PID + "=" + ProcessHandle.current().pid());
        }
        command.addAll(request.jvm().options());
        command.add(StudentHarness.class.getName());
        command.addAll(sandbox.isConfined() ? request.harnessArguments()
                : SandboxedProcess.unconfinedArguments(request.harnessArguments(), request.binds()));
        return command;
    }

    /** The request's folders, and the harness's jar and archive. */
    List<Bind> binds(Request request) {
        List<Bind> binds = new ArrayList<>(request.binds());
        binds.add(new Bind(harness, HARNESS, false));
        if (sharedArchive != null) {
            binds.add(new Bind(sharedArchive, ARCHIVE, false));
        }
        return binds;
    }
}
