package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Run;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Started;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The warm compiler's folder as a file system of its own (as root, where the sandbox mounts one):
 * what a compile may write there, and what is left of it. The compiler here is a shell that
 * answers each request as the harness's compile server does, after doing what the test says to
 * the request's folder.
 */
class CompileServerTest {

    private static final Duration LIMIT = Duration.ofSeconds(60);

    @TempDir
    Path dir;

    private Sandbox sandbox;
    private Path folder;
    private CompileServer server;
    private final AtomicInteger starts = new AtomicInteger();

    @BeforeEach
    void aSandboxThatMountsFileSystems() throws Exception {
        assumeThat(OutputDisk.canMount(Files.createDirectory(dir.resolve("scratch"))))
                .as("a tmpfs can be mounted here (as root)").isTrue();
        try {
            sandbox = Sandbox.confined().forJob(0).forCompiler();
        } catch (Sandbox.Unavailable e) {
            assumeThat(e.getMessage()).as("bubblewrap is needed").isNull();
        }
        folder = Files.createDirectory(dir.resolve("compiler"));
    }

    @AfterEach
    void stop() {
        if (server != null) {
            server.stop();
        }
    }

    @Test
    void aCompileThatMakesMoreFilesThanTheCapFailsWithTheCapsWordsAndTheKernelStopsItAtTheFileSystemsSize()
            throws Exception {
        server = compiler("mkdir -p \"$d/classes\" && cd \"$d/classes\" && seq 1 10100 | xargs touch 2>/dev/null; "
                + "ls -f | wc -l; cd /");
        Path request = server.newRequest();

        Run run = server.compile(request, "Sphere.java", "Renderer.java", LIMIT);

        assertThat(run.limitReached()).as("the compile's total").isEqualTo(
                new LimitReached(NoImage.DISK_LIMIT, OutputCount.TOO_MANY_ENTRIES));
        assertThat(Long.parseLong(run.outputTail().strip())).as("the files the compiler could make (and . and ..)")
                .isLessThanOrEqualTo(OutputDisk.INODES + 2);
    }

    @Test
    void stoppingUnmountsTheCompilersFileSystemAndLeavesItsFolderEmpty() throws Exception {
        server = compiler("mkdir -p \"$d/classes\" && touch \"$d/classes/Sphere.class\"");
        server.compile(server.newRequest(), "Sphere.java", "Renderer.java", LIMIT);

        server.stop();

        assertThat(Files.readString(Path.of("/proc/self/mountinfo"))).as("the mounts")
                .doesNotContain(" " + folder.toRealPath() + " ");
        try (Stream<Path> left = Files.list(folder)) {
            assertThat(left).as("what is in the compiler's folder on the host's disk").isEmpty();
        }
    }

    @Test
    void compilesThatLeaveNothingBehindShareOneCompilerAndOneFileSystem() throws Exception {
        server = compiler("mkdir -p \"$d/classes\" && touch \"$d/classes/Sphere.class\"");
        for (int i = 0; i < 3; i++) {
            Path request = server.newRequest();
            server.compile(request, "Sphere.java", "Renderer.java", LIMIT);
            server.takeOutput(request);
            server.done(request);
        }

        assertThat(starts).as("the compilers started").hasValue(1);
        assertThat(Files.readString(Path.of("/proc/self/mountinfo")).split(" " + folder.toRealPath() + " ", -1))
                .as("the mounts on the compiler's folder").hasSize(2);
    }

    @Test
    void aRequestAfterOneThatLeftSomethingBehindGetsAnEmptyFileSystemAndANewCompiler() throws Exception {
        server = compiler("mkdir -p \"$d/classes\" && touch \"$1/left-behind-$n\"");
        Path first = server.newRequest();
        server.compile(first, "Sphere.java", "Renderer.java", LIMIT);
        server.done(first);

        Path second = server.newRequest();
        server.compile(second, "Sphere.java", "Renderer.java", LIMIT);

        assertThat(folder.resolve("left-behind-0")).as("what the first compile left").doesNotExist();
        assertThat(starts).as("the compilers started: one for each file system").hasValue(2);
    }

    /**
     * A compile server whose compiler, for each request, runs {@code action} (with the folder as
     * {@code $1} and the request's output folder as {@code $d}) and then answers that it compiled.
     */
    private CompileServer compiler(String action) {
        String script = "while read n; do d=\"$1/$n/" + StudentHarness.OUTPUT_FOLDER + "\"; " + action + "; echo \""
                + StudentHarness.COMPILED + " $n 0\"; done";
        return new CompileServer(sandbox, folder, (compilerSandbox, exchange, timeLimit) -> {
            starts.incrementAndGet();
            return new Started(new ProcessBuilder("/bin/sh", "-c", script, "sh", exchange.toString())
                    .redirectErrorStream(true).start(), null);
        });
    }
}
