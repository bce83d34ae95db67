package gfx.tick1.command.grade;

import gfx.tick1.command.shared.grader.grading.HiddenVerdict;
import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.CliRun;
import gfx.tick1.Tick1;
import gfx.tick1.Tick1Jvm;
import gfx.tick1.command.shared.kit.StarterKit;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Lock;
import java.util.concurrent.locks.ReentrantReadWriteLock;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInfo;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.Execution;
import org.junit.jupiter.api.parallel.ExecutionMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The hostile submissions of {@code src/test/resources/students/attacks}, each graded through the
 * real {@code tick1 grade}, in a JVM of its own with a small heap (so that a grader that needs
 * more memory than that fails with exit status 4). Every attack must fail with a reason that says
 * what happened, and leave the secret nowhere, every file outside the work folder as it was, no
 * process behind, and the next student's grade as it would have been.
 * <p>
 * The grades run side by side: each waits mostly on the JVMs it starts. The files the attacks look
 * for are planted once for the class, with one secret, so that no test's planting can hide another's
 * harm; the few tests that share more than that (the host's page cache, a file in /usr, the processes
 * an attack starts) take a lock.
 */
@Execution(ExecutionMode.CONCURRENT)
@Order(1)   // the longest class: it starts first (junit-platform.properties)
class GradeAttackTest {

    /** The secret file and the victim as the attacks' sources name them. */
    private static final String SECRET_IN_ATTACKS = "/tmp/tick1-attack-secret.txt",
            VICTIM_IN_ATTACKS = "/tmp/tick1-attack-victim.txt";
    /**
     * This run's secret file and victim, which the test writes in the attacks' sources in place of theirs: names of
     * this run's own, as another run of these tests (another clone's) may plant and delete its own at the same time.
     */
    private static final String RUN = Long.toHexString(Double.doubleToLongBits(Math.random()));
    private static final Path SECRET = Path.of("/tmp/tick1-attack-secret-" + RUN + ".txt");
    private static final Path VICTIM = Path.of("/tmp/tick1-attack-victim-" + RUN + ".txt");
    /**
     * The port the attacks' sources send to: the test listens on a free port of its own, so that it can run beside
     * anything, and writes that port in its place.
     */
    private static final String LISTENER_PORT_IN_ATTACKS = "47811";
    private static final String VICTIM_TEXT = "the launcher: do not change\n";
    /** The grader's heap in these tests: far less than decoding a 40000 x 40000 image would take. */
    private static final String GRADER_HEAP = "-Xmx160m";

    private static final String[] SMALL = {"--width", "160", "--height", "120"};
    /**
     * The grades' time limit, in seconds: one the code compiles within on a busy machine, with the other grades
     * beside it. Each attack ends its runs itself, or a limit that is not time stops them, long before it.
     */
    private static final String TIME_LIMIT = "30";
    /**
     * The time limit of the one attack that ends only at the time limit, in seconds: shorter than {@link #TIME_LIMIT}
     * (the attack holds a worker of the test run until it), still one a correct solution compiles within on a busy
     * machine.
     */
    private static final String FIFO_TIME_LIMIT = "15";

    @TempDir
    Path dir;

    /** The secret planted for the whole class: every test looks for this one. */
    private static String secret;
    private ServerSocket listener;
    /**
     * Where {@link #aSceneLinkedToAFileDirectlyInUsrIsHiddenFromTheCode} puts the organiser's scene: a name of
     * this test's own, which the test writes in the attack's source in place of its name.
     */
    private Path hiddenSceneInUsr;
    /** The graders' temporary folder, where their work folders go: the test's own, as other grades may run. */
    private Path temporary;

    /**
     * Held by each test while it runs: to write by the tests {@link Alone}, to read by the others, which run
     * side by side.
     */
    private static final ReentrantReadWriteLock MACHINE = new ReentrantReadWriteLock(true);

    @BeforeAll
    static void theSandboxCanRunHere() throws InterruptedException {
        try {
            Sandbox.confined();
        } catch (Sandbox.Unavailable e) {
            assumeThat(e.getMessage()).as("bubblewrap is needed for the attack tests").isNull();
        }
    }

    @BeforeAll
    static void plantTheSecretAndTheVictim() throws IOException {
        removeTheLeaks();
        secret = "tick1-secret-" + Long.toHexString(Double.doubleToLongBits(Math.random()));
        Files.writeString(SECRET, secret);
        Files.writeString(VICTIM, VICTIM_TEXT);
    }

    @AfterAll
    static void removeThem() throws IOException {
        Files.deleteIfExists(SECRET);
        Files.deleteIfExists(VICTIM);
        removeTheLeaks();
    }

    /**
     * On a test that needs the machine to itself: its attack starts processes that every test's check looks
     * for, or it counts on the host's page cache, which every grade's start reads the JDK's files into.
     */
    @Target(ElementType.METHOD)
    @Retention(RetentionPolicy.RUNTIME)
    private @interface Alone {
    }

    private Lock held;

    @BeforeEach
    void takeTheMachine(TestInfo test) {
        held = test.getTestMethod().orElseThrow().isAnnotationPresent(Alone.class) ? MACHINE.writeLock()
                : MACHINE.readLock();
        held.lock();
    }

    @AfterEach
    void giveTheMachineBack() {
        held.unlock();
    }

    @BeforeEach
    void openTheListener() throws IOException {
        listener = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        hiddenSceneInUsr = Path.of("/usr/tick1-attack-hidden-scene-" + RUN + "-" + listener.getLocalPort() + ".xml");
        listener.setSoTimeout(200);
        // The sandbox's user must be able to reach the work folder in it.
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx--x--x"));
        temporary = Files.createDirectory(dir.resolve("tmp"), PosixFilePermissions.asFileAttribute(
                PosixFilePermissions.fromString("rwx--x--x")));
    }

    @AfterEach
    void closeTheListener() throws IOException {
        listener.close();
    }

    /** Deletes what an attack may have left where {@link #leaks()} looks: for the class, as its tests run at once. */
    private static void removeTheLeaks() throws IOException {
        try (Stream<Path> leaks = Files.list(Path.of("/tmp"))) {
            for (Path leak : leaks.filter(f -> f.getFileName().toString().startsWith("tick1-attack-leak")).toList()) {
                Files.delete(leak);
            }
        }
        Files.deleteIfExists(Path.of("/usr/tick1-attack-leak.txt"));
    }

    /** One grade in a JVM of its own: what it printed, its exit status, and whether it ended. */
    private record Grade(int status, String output, boolean ended) {
    }

    private Grade grade(String attack, String... options) throws IOException, InterruptedException {
        Path student = Files.createDirectories(dir.resolve(attack));
        Path sphere = student.resolve("Sphere.java"), renderer = student.resolve("Renderer.java");
        String folder = "/students/attacks/" + attack + "/";
        String first = resourceOr(folder + RENDER_FIRST, "");
        if (!first.isEmpty()) {
            // The correct solution, whose render first does what the attack does.
            StudentSolution attacking = StudentSolution.correct().editRenderer(RENDER, RENDER + first);
            Files.writeString(sphere, toTheListener(attacking.sphere()));
            Files.writeString(renderer, toTheListener(attacking.renderer()));
        } else {
            Files.writeString(sphere, toTheListener(resourceOr(folder + "Sphere.java", StarterKit.source("Sphere"))));
            Files.writeString(renderer, toTheListener(resourceOr(folder + "Renderer.java", null)));
        }
        return gradeFilesAs(List.of(), null, temporary,
                STARTS_PROGRAMS.contains(attack), sphere, renderer, options);
    }

    /** An attack's source with the port it sends to made this test's listener's, the files it looks for this run's. */
    private String toTheListener(String source) {
        return source.replace(LISTENER_PORT_IN_ATTACKS, Integer.toString(listener.getLocalPort()))
                .replace(SECRET_IN_ATTACKS, SECRET.toString()).replace(VICTIM_IN_ATTACKS, VICTIM.toString())
                .replace(HIDDEN_SCENE_IN_USR_IN_ATTACKS, hiddenSceneInUsr.toString());
    }

    /**
     * The attacks that start programs to test a limit against what they can do (those of the host's
     * {@link #ATTACK_TOOLS} shows, or a program the code wrote): their grades let the runs start
     * processes, which a real grade refuses.
     */
    private static final Set<String> STARTS_PROGRAMS = Set.of("deep-tree", "fifo-progress",
            "memory-in-many-processes", "outlive-the-grade", "reserve-the-disk", "unreadable-progress",
            "native-code-from-its-own-files");

    /**
     * The host's programs the attacks start, which the sandbox shows them (a real grade shows none
     * but java): so that the limits are tested against what the programs can do that Java cannot.
     */
    private static final List<String> ATTACK_TOOLS = List.of("/bin/sh", "/usr/bin/setsid", "/usr/bin/sleep",
            "/usr/bin/head", "/usr/bin/tail", "/usr/bin/mkfifo", "/usr/bin/touch", "/usr/bin/chmod",
            "/usr/bin/fallocate", "/usr/bin/mkdir", "/usr/bin/cat", "/usr/bin/ln", "/usr/bin/dd", "/usr/bin/rm",
            "/usr/bin/seq");

    /** An attack's file of the lines the correct solution's render runs first, in place of its own files. */
    private static final String RENDER_FIRST = "render-first.java.txt";
    /** The line of the correct solution's Renderer.java that those lines follow. */
    private static final String RENDER = "    public BufferedImage render(Scene scene) {\n";

    private Grade gradeFiles(Path sphere, Path renderer, String... options) throws IOException, InterruptedException {
        return gradeFilesAs(List.of(), null, temporary, false, sphere, renderer,
                options);
    }

    /**
     * A grade started by {@code launcher} (setpriv: as another user), with this class path and temporary folder; with
     * a null class path, as {@link Tick1Jvm} starts tick1, whose folder in build/ only the tests' user can read.
     */
    private Grade gradeFilesAs(List<String> launcher, String classPath, Path temporaryFolder, boolean processes,
            Path sphere, Path renderer, String... options) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(launcher);
        command.addAll(CliRun.java());
        command.addAll(List.of(
                GRADER_HEAP, "-Djava.awt.headless=true", "-Djava.io.tmpdir=" + temporaryFolder,
                "-Dtick1.grade.sandboxAlsoShows=" + String.join(File.pathSeparator, ATTACK_TOOLS),
                "-Dtick1.grade.sandboxAllowsProcesses=" + processes));
        command.addAll(classPath == null ? Tick1Jvm.mainClass() : List.of("-cp", classPath, Tick1.class.getName()));
        command.addAll(List.of("grade", "--sphere", sphere.toString(), "--renderer", renderer.toString()));
        if (!List.of(options).contains("--report")) {
            command.addAll(List.of("--report", dir.resolve("report").toString()));
        }
        command.addAll(List.of(SMALL));
        if (!List.of(options).contains("--time-limit")) {
            command.addAll(List.of("--time-limit", TIME_LIMIT));
        }
        command.addAll(List.of(options));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        // A secret in the grader's own environment, as an API token might be.
        builder.environment().put("TICK1_ATTACK_TOKEN", secret);
        Process process = builder.start();
        process.getOutputStream().close();
        ByteArrayOutputStream output = new ByteArrayOutputStream();
        Thread reader = new Thread(() -> {
            try (InputStream in = process.getInputStream()) {
                in.transferTo(output);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        });
        reader.start();
        // Not a timing check: a bound on how long to wait for a grade that may hang.
        boolean ended = process.waitFor(120, TimeUnit.SECONDS);
        if (!ended) {
            process.destroyForcibly().waitFor();
        }
        reader.join();
        return new Grade(ended ? process.exitValue() : -1, output.toString(StandardCharsets.UTF_8), ended);
    }

    /** The checks every attack must pass, whatever it tried. */
    private void assertFailedAndHarmedNothing(Grade grade) throws IOException, InterruptedException {
        assertThat(grade.ended()).as("the grade ended:\n" + grade.output()).isTrue();
        assertThat(grade.status()).as(grade.output()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(grade.output()).as("the verdict").contains("FAILED")
                .doesNotContain("\n" + SubmissionGrader.CONGRATULATIONS);
        assertThat(grade.output()).as("the secret in the grader's output").doesNotContain(secret);
        assertThat(Files.readString(VICTIM)).as("a file outside the work folder").isEqualTo(VICTIM_TEXT);
        assertThat(leaks()).as("files the attack left behind").isEmpty();
        assertThat(listenerHeard()).as("what reached the loopback listener").isEmpty();
        assertThat(workFolders()).as("grade work folders left in the temporary folder").isEmpty();
        assertThat(processesOf("tick1-attack")).as("processes of the student's left running").isEmpty();
    }

    @Test
    void codeThatCopiesTheReferenceRendererFindsNoneToCopy() throws Exception {
        Grade grade = grade("copy-the-reference");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: the code threw",
                "ClassNotFoundException: gfx.tick1.engine.scene.SceneLoader");
    }

    /**
     * The built-in scenes are public, so their reference images can be made by anyone and carried in
     * the code: an untouched Sphere (no ray ever hits) and a Renderer whose render returns the
     * reference image of the scene, chosen by the light's x. The images match; traced through the
     * student's own intersectionWith and illuminate, the sampled pixels do not.
     */
    @Test
    void imagesCarriedInTheCodeInsteadOfTracedFailAsNotComingFromIt() throws Exception {
        StringBuilder images = new StringBuilder();
        for (String name : gfx.tick1.engine.scene.BundledScenes.GRADING) {
            java.io.ByteArrayOutputStream png = new java.io.ByteArrayOutputStream();
            gfx.tick1.engine.image.PngOutput.write(new gfx.tick1.engine.render.ReferenceRenderer(160, 120)
                    .render(gfx.tick1.engine.scene.BundledScenes.load(name)), png);
            images.append("    private static final String ").append(name.equals("tick1.xml") ? "TICK1" : "HIDDEN")
                    .append(" = \"").append(java.util.Base64.getEncoder().encodeToString(png.toByteArray()))
                    .append("\";\n");
        }
        String renderer = StarterKit.source("Renderer")
                .replace("public class Renderer {\n", "public class Renderer {\n" + images)
                .replace("    public BufferedImage render(Scene scene) {\n", """
                    public BufferedImage render(Scene scene) {
                        String png = scene.getPointLight().getPosition().x > 0 ? TICK1 : HIDDEN;
                        try {
                            return javax.imageio.ImageIO.read(new java.io.ByteArrayInputStream(
                                    java.util.Base64.getDecoder().decode(png)));
                        } catch (java.io.IOException e) {
                            throw new java.io.UncheckedIOException(e);
                        }
                    }

                    public BufferedImage unused(Scene scene) {
                """);
        Path student = Files.createDirectories(dir.resolve("embedded-images"));
        Path sphereFile = Files.writeString(student.resolve("Sphere.java"), StarterKit.source("Sphere"));
        Path rendererFile = Files.writeString(student.resolve("Renderer.java"), renderer);
        Grade grade = gradeFiles(sphereFile, rendererFile);
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).as("the copied tick1.xml").contains("tick1.xml: FAIL: "
                + SubmissionGrader.NOT_FROM_THE_CODE + ": traced through your own intersectionWith and illuminate");
        assertThat(grade.output()).as("the copied hidden scene, in fixed words")
                .contains(": FAIL: " + SubmissionGrader.NOT_FROM_THE_CODE + " (checked on sampled pixels)");
    }

    @Test
    void codeThatStealsSecretsFindsNoneAndCannotSendThem() throws Exception {
        Grade grade = grade("steal-secrets");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains(SECRET + ": NoSuchFileException", "ConnectException")
                .doesNotContain("/proc/1/environ", "HOME=", "USER=", "TICK1_ATTACK_TOKEN");
    }

    @Test
    void codeThatDeletesAndChangesFilesOutsideItsFolderCannot() throws Exception {
        Grade grade = grade("damage-files");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("Read-only file system").doesNotContain("changed the victim",
                "deleted the victim", "wrote into");
    }

    @Test
    @Alone
    void processesTheCodeStartsDoNotOutliveTheGradeNorTouchTheNextOne() throws Exception {
        Grade attack = grade("outlive-the-grade");
        assertFailedAndHarmedNothing(attack);
        Path student = Files.createDirectories(dir.resolve("next-student"));
        Path[] files = StudentSolution.correct().writeTo(student);
        Grade next = gradeFiles(files[0], files[1]);
        assertThat(next.status()).as(next.output()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(processesOf("tick1-attack")).isEmpty();
    }

    @Test
    void linksPlantedWhereTheGraderReadsAreNotFollowed() throws Exception {
        Grade grade = grade("link-to-a-secret");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: 19200 of 19200 pixels differ");
    }

    @Test
    void aFifoWhereTheGraderReadsCannotHangIt() throws Exception {
        // The FIFO holds the render until the limit whatever its length.
        Grade grade = grade("fifo-progress", "--time-limit", FIFO_TIME_LIMIT);
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: no image within the time limit of " + FIFO_TIME_LIMIT
                + " s");
    }

    @Test
    void aGiantPngIsRefusedFromItsHeaderWithoutDecodingIt() throws Exception {
        Grade grade = grade("giant-png");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: the image written for this scene is unusable: "
                + "the image is 40000 x 40000, expected 160 x 120");
    }

    @Test
    void aSourceThatBlowsUpTheCompilerFailsInsideTheMemoryLimit() throws Exception {
        // A long time limit, so that only memory can stop the compiler, however loaded the machine.
        Grade grade = grade("compiler-bomb", "--memory", "64", "--time-limit", "120");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("FAILED: the code could not be compiled: the compiler ran out of memory");
    }

    @Test
    void controlCharactersCannotRewriteTheVerdict() throws Exception {
        Grade grade = grade("spoof-the-verdict");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).as("control characters in the report")
                .doesNotContain("\r", "\033", "\007", "\u202E", "\u200B");
        // The verdict is the report's last line; only the sandbox's warnings on this machine come after it.
        assertThat(SandboxWarnings.stripped(grade.output()).lines()).as(grade.output()).last().asString()
                .startsWith("FAILED: 2 of 2 scenes wrong.");
    }

    @Test
    void aTreeDeeperThanAPathMayBeLongStopsTheRunIsDeletedAndNoNameOfItIsPrinted() throws Exception {
        Grade grade = grade("deep-tree");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: the program was stopped: its output folder holds "
                + "something the grader cannot count (a folder made unreadable, or deeper than a path may be long)")
                .doesNotContain("\u001b", "cannot delete");
    }

    @Test
    void diskSpaceReservedBeyondAFilesSizeIsRefused() throws Exception {
        Grade grade = grade("reserve-the-disk");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).as("fallocate --keep-size in the sandbox")
                .contains("tick1.xml: FAIL: the code threw java.lang.IllegalStateException: reserved 0 GiB, then: "
                        + "fallocate: fallocate failed");
    }

    /** Sparse files (counted by their size) and many small files, below where a walk of 64 levels looked. */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "deep-sparse-files | it wrote more than 256 MiB to its output folder",
        "deep-many-files   | it made more than 10000 files and folders in its output folder"})
    void whatTheCodeWritesAnyDepthDownItsOutputFolderIsCounted(String attack, String limit) throws Exception {
        Grade grade = grade(attack, "--time-limit", "60");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: the program was stopped: " + limit);
    }

    /**
     * Files deleted while the code keeps them (open, or mapped), which no walk of names sees: the
     * output folder's file system holds them to its size and number of files, and a run found
     * holding more than the limit is stopped with the limit's words.
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "hold-deleted-files       | it wrote more than 256 MiB to its output folder",
        "hold-deleted-small-files | it made more than 10000 files and folders in its output folder"})
    void filesTheCodeDeletesWhileHoldingThemCountAgainstItsOutputFolder(String attack, String limit)
            throws Exception {
        assumeThat(Sandbox.confined().enforcement().diskNotEnforced()).as("the kernel holds the output folder here")
                .isNull();
        Grade grade = grade(attack, "--time-limit", "60");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: the program was stopped: " + limit);
    }

    @Test
    void aCorrectRenderThatLeavesTheRunNoThreadIsToldItReachedTheLimitOfProcessesAndThreads() throws Exception {
        // Without a control group, threads are held only by the run's address space, and the stacks of the threads
        // the code starts leave no room to load a library: the run fails with that error instead.
        assumeThat(totalsEnforced()).as("a control group, which limits processes and threads, can be made here")
                .isTrue();
        Grade grade = grade("leave-no-thread");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).as("what the grade says of a correct image the run had no thread left to check")
                .contains("tick1.xml: FAIL: the image could not be checked against your Sphere and Renderer: the "
                        + "program reached the limit of processes and threads")
                .contains("hidden.xml: FAIL: " + HiddenVerdict.PROCESSES.words() + "\n")
                .doesNotContain("OutOfMemoryError", "gfx.tick1.command");
    }

    @Test
    void threadsCoresAndNativeMemoryAreLimited() throws Exception {
        Grade grade = grade("exceed-limits", "--memory", "64");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("stopped at").contains("threads, on 1 cores")
                .doesNotContain("allocated 2200 MiB");
    }

    @Test
    void theHiddenScenesContentNeverReachesTheReport() throws Exception {
        Grade grade = grade("quote-the-hidden-scene");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("hidden.xml: FAIL: " + HiddenVerdict.THREW.words() + "\n",
                "SCENES /scenes/0.xml");
        String tick1 = resourceOr("/gfx/tick1/scenes/tick1.xml", null);
        assertThat(resourceOr("/gfx/tick1/scenes/hidden.xml", null).lines().map(String::strip)
                .filter(line -> line.length() > 8 && !tick1.contains(line)))
                .as("lines of the hidden scene").isNotEmpty()
                .allSatisfy(line -> assertThat(grade.output()).doesNotContain(line));
        assertThat(dir.resolve("report").resolve("2-hidden-expected.png")).doesNotExist();
    }

    @Test
    void madeUpClassNamesAndStackFramesCannotCarryAHiddenSceneOut() throws Exception {
        Grade grade = grade("forge-the-stack-trace");
        assertFailedAndHarmedNothing(grade);
        String hidden = grade.output().substring(grade.output().indexOf("hidden.xml: FAIL"));
        assertThat(grade.output()).as("the public scene's report keeps the message").contains("HIDDENLEAK");
        assertThat(hidden).as("the hidden scene's report").doesNotContain("HIDDENLEAK")
                .startsWith("hidden.xml: FAIL: " + HiddenVerdict.THREW.words() + "\nFAILED");
    }

    @Test
    void trueStackFramesCannotCarryAHiddenSceneOutInTheirMethodNamesOrLineNumbers() throws Exception {
        Grade grade = grade("frames-channel");
        assertFailedAndHarmedNothing(grade);
        String hidden = grade.output().substring(grade.output().indexOf("hidden.xml: FAIL"));
        assertThat(grade.output()).as("the public scene's report keeps the frames")
                .containsPattern("tick1.xml: FAIL: the code threw java.lang.IllegalStateException: (low|high)");
        assertThat(hidden).as("the hidden scene's report: fixed words only")
                .startsWith("hidden.xml: FAIL: " + HiddenVerdict.THREW.words() + "\nFAILED")
                .doesNotContain("leakEven", "leakOdd", "Renderer.java:");
    }

    /**
     * A wrong image whose every pixel is a byte of the scene it was given: the public scene's
     * figures show it, the hidden scene's report is its verdict in fixed words and nothing more.
     */
    @Test
    void aWrongHiddenImageIsOneFixedVerdictWithoutFigures() throws Exception {
        Grade grade = grade("figures-of-the-hidden-scene");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).as("the public scene's figures").contains("tick1.xml: FAIL: 19200 of 19200 "
                + "pixels differ");
        String hidden = grade.output().substring(grade.output().indexOf("hidden.xml: "));
        assertThat(hidden).as("the hidden scene's report")
                .startsWith("hidden.xml: FAIL: " + HiddenVerdict.WRONG.words() + "\nFAILED: 2 of 2 scenes wrong.");
    }

    /**
     * The organiser's scenes in a folder under /usr, where the code looks for them, and would
     * quote them in the public scene's report: the runs see no folder of the host's.
     */
    @Test
    void organisersScenesUnderUsrAreHiddenFromTheCode() throws Exception {
        assumeThat(Files.isWritable(Path.of("/usr"))).as("a folder can be made in /usr (as root)").isTrue();
        // A run of these tests stopped before its finally leaves the folder behind.
        Files.deleteIfExists(ORGANISERS_SCENES.resolve("secret-scene.xml"));
        Files.deleteIfExists(ORGANISERS_SCENES);
        Path scenes = Files.createDirectory(ORGANISERS_SCENES);
        try {
            Files.writeString(scenes.resolve("secret-scene.xml"), secretScene());
            Grade grade = grade("read-the-organisers-scenes", "--scenes", scenes.toString());
            assertFailedAndHarmedNothing(grade);
            assertThat(grade.output()).as("what the code found in the folder: no folder at all")
                    .contains("tick1.xml: FAIL: the code threw java.lang.IllegalStateException: read: "
                            + "java.nio.file.NoSuchFileException: " + ORGANISERS_SCENES + "\n");
        } finally {
            Files.deleteIfExists(scenes.resolve("secret-scene.xml"));
            Files.deleteIfExists(scenes);
        }
    }

    /** Where {@link #organisersScenesUnderUsrAreHiddenFromTheCode} puts the organiser's scenes. */
    private static final Path ORGANISERS_SCENES = Path.of("/usr/tick1-attack-scenes");

    /**
     * A scene of the organiser's --scenes folder that is a link to a file directly in /usr (not in a
     * folder below it, which could be hidden under an empty folder): the code reads it there.
     */
    @Test
    void aSceneLinkedToAFileDirectlyInUsrIsHiddenFromTheCode() throws Exception {
        assumeThat(Files.isWritable(Path.of("/usr"))).as("a file can be made in /usr (as root)").isTrue();
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        try {
            Files.writeString(hiddenSceneInUsr, secretScene());
            Files.createSymbolicLink(scenes.resolve("secret-scene.xml"), hiddenSceneInUsr);
            Grade grade = grade("read-a-scene-in-usr", "--scenes", scenes.toString());
            assertFailedAndHarmedNothing(grade);
            assertThat(grade.output()).as("what the code read there: no scene")
                    .contains("tick1.xml: FAIL: the code threw java.lang.IllegalStateException: read: [")
                    .doesNotContain("<scene>", "point-light");
        } finally {
            Files.deleteIfExists(hiddenSceneInUsr);
        }
    }

    /** Where the attack that reads a scene in /usr looks for it, as its source names it. */
    private static final String HIDDEN_SCENE_IN_USR_IN_ATTACKS = "/usr/tick1-attack-hidden-scene.xml";

    /**
     * A scene of the organiser's --scenes folder (not in /usr) with another name in /usr, a hard
     * link (as a copy, a backup or a version-control object of it would be), where the attack of
     * {@link #aSceneLinkedToAFileDirectlyInUsrIsHiddenFromTheCode} looks: the runs see no file of
     * /usr but the JDK's and its libraries, so the other name is not there either.
     */
    @Test
    void aSceneWithAHardLinkInUsrIsHiddenFromTheCode() throws Exception {
        assumeThat(Files.isWritable(Path.of("/usr"))).as("a file can be made in /usr (as root)").isTrue();
        Path scenes = secretScenes();
        Path scene = scenes.resolve("secret-scene.xml");
        try {
            try {
                Files.createLink(hiddenSceneInUsr, scene);
            } catch (IOException e) {
                assumeThat(e).as("/usr and the test's folder are one file system").isNull();
            }
            Grade grade = grade("read-a-scene-in-usr", "--scenes", scenes.toString());
            assertFailedAndHarmedNothing(grade);
            assertThat(grade.output()).as("what the code read there: no scene")
                    .contains("tick1.xml: FAIL: the code threw java.lang.IllegalStateException: read: [")
                    .doesNotContain("<scene>", "point-light");
        } finally {
            Files.deleteIfExists(hiddenSceneInUsr);
        }
    }

    /** The organiser's hidden scene with this test's secret in a comment its scene element begins with. */
    private String secretScene() throws IOException {
        return resourceOr("/gfx/tick1/scenes/hidden.xml", null).replace("<scene>", "<scene><!-- " + secret + " -->");
    }

    /** A --scenes folder of the test's, holding {@link #secretScene()} as secret-scene.xml. */
    private Path secretScenes() throws IOException {
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        Files.writeString(scenes.resolve("secret-scene.xml"), secretScene());
        return scenes;
    }

    @Test
    void theSandboxsOwnFileSystemsInMemoryAreReadOnly() throws Exception {
        Grade grade = grade("fill-the-tmpfs");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("/dev/shm: 0 MiB in all (/dev/shm/fill-0 (Read-only file system))")
                .containsPattern("; /fill: stopped after 0 MiB \\(/fill \\((Read-only file system|Permission "
                        + "denied)\\)")
                .containsPattern("/dev/fill: stopped after 0 MiB \\(/dev/fill \\((Read-only file system|Permission "
                        + "denied)\\)");
    }

    /**
     * Machine code of the student's choosing would read the machine in ways no Java call can (its
     * counters, its timers, calls Java never makes). From Java alone, a run can write a library
     * with code or a program into its output folder, but neither is mapped as code (as root the
     * folder is a file system on which nothing executes: the program is started here with
     * processes allowed, so that it is noexec that refuses it), and it has no /proc in which to
     * write its own code. The attack renders as the correct solution does only when all three are
     * refused, in tick1.xml's run and in the hidden scene's. (A library with no code in it still
     * loads, and its relocations write where it asks: docs/grading.md's trust model says so.)
     */
    @Test
    void aRunCannotMapFilesItWroteAsCodeNorWriteItsCodeThroughProc() throws Exception {
        assumeThat(Sandbox.confined().enforcement().diskNotEnforced())
                .as("the output folder is a file system of its own (as root)").isNull();
        Grade grade = grade("native-code-from-its-own-files");
        assertThat(grade.output()).as("what the attack did").doesNotContain("native code:");
        assertThat(grade.status()).as("tick1.xml's run and the hidden scene's both refused it:\n" + grade.output())
                .isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(Files.readString(VICTIM)).as("a file outside the work folder").isEqualTo(VICTIM_TEXT);
        assertThat(workFolders()).as("grade work folders left in the temporary folder").isEmpty();
    }

    /**
     * A JVM the code starts takes any option: with -XX:+EnableJVMCI (experimental, on in this JDK),
     * JVMCI's code cache installs bytes of the code's choosing as a method's compiled code and runs
     * them, with no sun.misc.Unsafe, no class in a package of the JDK's and no file that executes.
     * The attack renders as the correct solution does only when no machine code of its own ran, in
     * tick1.xml's run and in the hidden scene's.
     */
    @Test
    void aRunCannotRunMachineCodeOfItsOwnThroughAJvmItStartsWithJvmci() throws Exception {
        Grade grade = grade("machine-code-through-jvmci");
        assertThat(grade.output()).as("what the attack did").doesNotContain("machine code of its own");
        assertThat(grade.status()).as("tick1.xml's run and the hidden scene's both refused it:\n" + grade.output())
                .isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(workFolders()).as("grade work folders left in the temporary folder").isEmpty();
    }

    @Test
    void memorySpreadOverManyProcessesIsHeldToOneTotal() throws Exception {
        assumeThat(totalsEnforced()).as("a control group can be made here").isTrue();
        Grade grade = grade("memory-in-many-processes", "--memory", "64");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: the program used more than 576 MiB of memory in all");
    }

    @Test
    void whatTheCodeWritesToItsOutputFolderIsCapped() throws Exception {
        Grade grade = grade("fill-the-output");
        assertFailedAndHarmedNothing(grade);
        assertThat(grade.output()).contains("tick1.xml: FAIL: the program was stopped: it wrote more than 256 MiB "
                + "to its output folder").doesNotContain("wrote 64 files");
    }

    @Test
    void filesTheCodeMadeUnreadableAreTheStudentsFailureWhenGradingAsANormalUser() throws Exception {
        assumeThat(SandboxNeeded.root()).as("the tests run as root, who can grade as the user nobody (setpriv)")
                .isTrue();
        Path home = Files.createDirectory(dir.resolve("normal-user"));
        Path classPath = Files.createDirectory(home.resolve("class-path"));
        List<String> entries = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(java.io.File.pathSeparator)) {
            Path from = Path.of(entry);
            if (Files.exists(from)) {
                Path to = classPath.resolve(entries.size() + "-" + from.getFileName());
                copyTree(from, to);
                entries.add(to.toString());
            }
        }
        Path student = Files.createDirectories(home.resolve("student"));
        Files.writeString(student.resolve("Renderer.java"), resourceOr("/students/attacks/unreadable-progress/"
                + "Renderer.java", null));
        Files.writeString(student.resolve("Sphere.java"), StarterKit.source("Sphere"));
        Path tmp = Files.createDirectory(home.resolve("tmp"));
        try (Stream<Path> all = Files.walk(home)) {
            for (Path file : all.toList()) {
                Files.setAttribute(file, "unix:uid", NORMAL_USER);
                Files.setAttribute(file, "unix:gid", NORMAL_USER);
            }
        }
        Files.setPosixFilePermissions(home, PosixFilePermissions.fromString("rwx--x--x"));
        Grade grade = gradeFilesAs(List.of("/usr/bin/setpriv", "--reuid=" + NORMAL_USER, "--regid=" + NORMAL_USER,
                "--clear-groups"), String.join(java.io.File.pathSeparator, entries), tmp, true,
                student.resolve("Sphere.java"), student.resolve("Renderer.java"), "--report",
                home.resolve("report").toString());
        assertThat(grade.status()).as(grade.output()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(grade.output()).contains("tick1.xml: FAIL: ").doesNotContain("internal error",
                "AccessDeniedException");
        try (Stream<Path> left = Files.list(tmp)) {
            assertThat(left.toList()).as("work folders left").isEmpty();
        }
    }

    /** The user the normal-user grade runs as: nobody. */
    private static final int NORMAL_USER = 65534;

    /** Copies the folder {@code from}, with all it holds, to {@code to}. */
    static void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> all = Files.walk(from)) {
            for (Path file : all.toList()) {
                Files.copy(file, to.resolve(from.relativize(file).toString()));
            }
        }
    }

    /** Whether this machine gives each run a control group (the grade warns when it cannot). */
    private static boolean totalsEnforced() throws Sandbox.Unavailable, InterruptedException {
        return Sandbox.confined().enforcement().totalsNotEnforced() == null;
    }

    @Test
    void aTemporaryFolderTheSandboxCannotReachIsOneLineSayingWhatToDo() throws Exception {
        // Only root's sandbox runs as another user; a normal user's runs as that user, who reaches its own folders.
        assumeThat(SandboxNeeded.root()).as("the tests run as root, whose sandbox runs as another user").isTrue();
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx------"));
        Path[] files = StudentSolution.correct().writeTo(Files.createDirectories(dir.resolve("student")));
        Grade grade = gradeFiles(files[0], files[1]);
        assertThat(grade.status()).as(grade.output()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(grade.output()).isEqualTo("tick1 grade: " + dir + ": the sandbox's user cannot pass through this "
                + "folder to the work folder; grade with a temporary folder it can reach "
                + "(JAVA_OPTS=-Djava.io.tmpdir=/tmp)" + System.lineSeparator());
        assertThat(workFolders()).isEmpty();
    }

    @Test
    void sigtermStopsTheStudentsCodeAndDeletesTheWorkFolder() throws Exception {
        Process grade = loopingGrade(dir.resolve("grade.log"));
        assertThat(grade.descendants().map(p -> p.info().commandLine().orElse("")))
                .as("the student's code is running").anyMatch(line -> line.contains("StudentHarness render"));
        List<ProcessHandle> running = grade.descendants().toList();

        grade.destroy();   // SIGTERM
        assertThat(grade.waitFor(60, TimeUnit.SECONDS)).as("the grade ended").isTrue();
        for (ProcessHandle process : running) {
            process.onExit().get(30, TimeUnit.SECONDS);
        }
        assertThat(running).as("processes of the student's").noneMatch(ProcessHandle::isAlive);
        assertThat(workFolders()).as("grade work folders left in the temporary folder").isEmpty();
    }

    @Test
    void sigtermSaysInOneLineThatTheGradeWasStopped() throws Exception {
        Path log = dir.resolve("grade.log");
        Process grade = loopingGrade(log);

        grade.destroy();   // SIGTERM
        assertThat(grade.waitFor(60, TimeUnit.SECONDS)).as("the grade ended").isTrue();
        assertThat(grade.exitValue()).as("the exit status").isNotZero();
        assertThat(Files.readString(log)).as("what the grade printed")
                .contains("tick1 grade: the grade was stopped").doesNotContain("internal error", "Exception");
    }

    /**
     * A grade, in a JVM of its own printing to {@code log}, of code that loops in its render:
     * returned once the student's code is running (waiting at most a minute).
     */
    private Process loopingGrade(Path log) throws IOException, InterruptedException {
        Path student = Files.createDirectories(dir.resolve("looping"));
        Path[] files = StudentSolution.correct().editSphere("double s = s1 > 0 ? s1 : s2;",
                "double s = s1 > 0 ? s1 : s2; while (s > 0) { }").writeTo(student);
        List<String> command = CliRun.java();
        command.addAll(List.of(GRADER_HEAP, "-Djava.io.tmpdir=" + temporary));
        command.addAll(Tick1Jvm.mainClass());
        command.addAll(List.of("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--time-limit", "600", "--width", "16", "--height", "12"));
        Process grade = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        // The student's code runs in a JVM whose class path is /harness.
        for (int i = 0; i < 600 && grade.descendants().noneMatch(p -> p.info().commandLine().orElse("")
                .contains("StudentHarness render")); i++) {
            Thread.sleep(100);
        }
        return grade;
    }

    private String resourceOr(String name, String otherwise) throws IOException {
        try (InputStream in = GradeAttackTest.class.getResourceAsStream(name)) {
            if (in == null) {
                assertThat(otherwise).as("test resource " + name).isNotNull();
                return otherwise;
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    private static List<Path> leaks() throws IOException {
        List<Path> found = new ArrayList<>();
        for (Path folder : List.of(Path.of("/tmp"), Path.of("/usr"), Path.of(System.getProperty("java.home")),
                Path.of(System.getProperty("user.home")), Path.of("").toAbsolutePath())) {
            try (Stream<Path> files = Files.list(folder)) {
                files.filter(f -> f.getFileName().toString().startsWith("tick1-attack-leak")).forEach(found::add);
            }
        }
        return found;
    }

    private String listenerHeard() throws IOException {
        StringBuilder heard = new StringBuilder();
        while (true) {
            try (Socket client = listener.accept()) {
                client.setSoTimeout(1000);
                heard.append(new String(client.getInputStream().readAllBytes(), StandardCharsets.UTF_8)).append('|');
            } catch (SocketTimeoutException e) {
                return heard.toString();
            }
        }
    }

    /** Grade work folders are made in the temporary folder; each grade deletes its own. */
    private List<Path> workFolders() throws IOException {
        try (Stream<Path> files = Files.list(temporary)) {
            return files.filter(f -> f.getFileName().toString().startsWith("tick1-grade")).toList();
        }
    }

    /** The processes whose command line mentions {@code marker}. */
    private static List<String> processesOf(String marker) {
        return ProcessHandle.allProcesses().filter(p -> p.pid() != ProcessHandle.current().pid())
                .map(p -> p.info().commandLine().orElse(""))
                .filter(line -> line.contains(marker) && !line.contains("GradeAttackTest")).toList();
    }
}
