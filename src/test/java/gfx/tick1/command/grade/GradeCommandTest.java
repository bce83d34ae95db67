package gfx.tick1.command.grade;

import static gfx.tick1.command.grade.Mistakes.DIFFUSE;
import static gfx.tick1.command.grade.Mistakes.HIT_REJECTED_ON_A_NEGATIVE_ROOT;
import static gfx.tick1.command.grade.Mistakes.NEAR_ROOT;
import static gfx.tick1.command.grade.Mistakes.ROOTS_ACCEPTED_AT_ZERO;
import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.grader.grading.HiddenVerdict;
import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.sandbox.RefusedNamespaces;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code tick1 grade} of one student through the real entry point, on student-style solutions: the
 * correct one, mistakes that only some scenes show, two mistakes at once, and ones that do not
 * compile or exit; what one student's grade prints, writes and refuses. Each mistake of the
 * catalogue, and a loop, a throw and a missing method, are graded once, in GradeCohortTest's
 * cohort, whose feedback files say what this command prints for them. Images are 160 x 120 to
 * keep the suite quick; every catalogue entry shows at that size (VariantRendererTest checks it).
 */
@ExtendWith(SandboxNeeded.class)
@Order(3)   // one of the longest classes: it starts early (junit-platform.properties)
class GradeCommandTest {

    private static final String[] SMALL = {"--width", "160", "--height", "120"};

    @TempDir
    Path dir;

    /**
     * Where the grades that several tests read are made, each in a folder of its own: {@link #twoMistakes},
     * {@link #twoMistakesWithoutTheSandbox}, {@link #correctOnTheCoursesScenes} and {@link #correctOnManyScenes}.
     */
    @TempDir
    static Path shared;
    private static CliRun twoMistakes, twoMistakesWithoutTheSandbox, correctOnTheCoursesScenes, correctOnManyScenes;

    /** Two mistakes in two methods: N.L left unclamped in illuminate, the far root taken in intersectionWith. */
    private static final StudentSolution TWO_MISTAKES = StudentSolution.correct()
            .editRenderer(DIFFUSE, "k_d * NdotL").editSphere(NEAR_ROOT, "double s = s2;");

    private CliRun grade(StudentSolution solution, String... options) throws IOException {
        return grade(dir, solution, options);
    }

    /** Grades {@code solution}, written into {@code folder}/student, with its report in {@code folder}/report. */
    private static CliRun grade(Path folder, StudentSolution solution, String... options) throws IOException {
        Path[] files = solution.writeTo(folder.resolve("student"));
        List<String> args = new java.util.ArrayList<>(List.of("grade", "--sphere", files[0].toString(),
                "--renderer", files[1].toString(), "--report", folder.resolve("report").toString()));
        args.addAll(List.of(SMALL));
        args.addAll(List.of(options));
        return CliRun.of(args.toArray(String[]::new));
    }

    /**
     * The grade, in {@link #shared}/courses-scenes, of the correct solution on the course's scenes, into a report
     * folder as a failing grade ({@link #twoMistakes}) left it, with the organiser's own notes.txt beside its
     * images: graded once, on first use, for the tests that read what it printed and left in the folder.
     */
    private static synchronized CliRun correctOnTheCoursesScenes() throws IOException {
        if (correctOnTheCoursesScenes == null) {
            assertThat(twoMistakes().status()).isEqualTo(GradeCommand.EXIT_FAIL);
            Path report = Files.createDirectories(shared.resolve("courses-scenes").resolve("report"));
            try (Stream<Path> earlier = Files.list(shared.resolve("two-mistakes").resolve("report"))) {
                for (Path image : earlier.toList()) {
                    Files.copy(image, report.resolve(image.getFileName()));
                }
            }
            assertThat(report.resolve("1-tick1-diff.png")).exists();
            Files.writeString(report.resolve("notes.txt"), "the organiser's own file");
            correctOnTheCoursesScenes = grade(shared.resolve("courses-scenes"), StudentSolution.correct());
        }
        return correctOnTheCoursesScenes;
    }

    @Test
    void theCorrectSolutionPassesWithTheCoursesWords() throws IOException {
        CliRun run = correctOnTheCoursesScenes();
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.out()).contains("tick1.xml: PASS", "hidden.xml: PASS")
                .endsWith(SubmissionGrader.CONGRATULATIONS + System.lineSeparator());
        assertThat(SandboxWarnings.stripped(run.err())).isEmpty();
    }

    @Test
    void aCorrectSolutionThatEncodesAJpegWithImageIoPasses() throws IOException {
        CliRun run = grade(StudentSolution.correct().editRenderer("    public BufferedImage render(Scene scene) {\n",
                """
                    public BufferedImage render(Scene scene) {
                        try {
                            javax.imageio.ImageIO.write(new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB), "jpg",
                                    new java.io.ByteArrayOutputStream());
                        } catch (java.io.IOException e) {
                            throw new java.io.UncheckedIOException(e);
                        }
                """));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.out()).contains("tick1.xml: PASS", "hidden.xml: PASS");
    }

    @Test
    void aCorrectSolutionThatTimesItselfWithTheManagementBeansAndHashesWithACipherPasses() throws IOException {
        CliRun run = grade(StudentSolution.correct().editRenderer("    public BufferedImage render(Scene scene) {\n",
                """
                    public BufferedImage render(Scene scene) {
                        System.out.println(java.lang.management.ManagementFactory.getThreadMXBean()
                                .getCurrentThreadCpuTime());
                        try {
                            javax.crypto.Mac.getInstance("HmacSHA256");
                        } catch (java.security.GeneralSecurityException e) {
                            throw new IllegalStateException(e);
                        }
                """));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.out()).contains("tick1.xml: PASS", "hidden.xml: PASS");
    }

    /** No run starts a process, and every run may start threads: the ways Java starts them all work. */
    @Test
    void aCorrectSolutionThatRendersBesideThreadsPoolsAndTimersPasses() throws IOException {
        CliRun run = grade(StudentSolution.correct().editRenderer("    public BufferedImage render(Scene scene) {\n",
                """
                    public BufferedImage render(Scene scene) {
                        long sum = java.util.stream.IntStream.range(0, 100_000).parallel().asLongStream().sum();
                        var pool = java.util.concurrent.Executors.newFixedThreadPool(2);
                        java.util.concurrent.ForkJoinPool forkJoin = new java.util.concurrent.ForkJoinPool(2);
                        try {
                            sum += pool.submit(() -> 1L).get() + forkJoin.submit(() -> 1L).get()
                                    + java.util.concurrent.CompletableFuture.supplyAsync(() -> 1L).join();
                            Thread thread = new Thread(() -> { });
                            thread.start();
                            thread.join();
                            java.util.Timer timer = new java.util.Timer(true);
                            timer.schedule(new java.util.TimerTask() {
                                @Override
                                public void run() {
                                }
                            }, 1);
                            timer.cancel();
                        } catch (InterruptedException | java.util.concurrent.ExecutionException e) {
                            throw new IllegalStateException(e);
                        } finally {
                            pool.shutdown();
                            forkJoin.shutdown();
                        }
                        java.util.logging.Logger.getLogger("render").info(sum + " on "
                                + Runtime.getRuntime().availableProcessors() + " cores, process "
                                + ProcessHandle.current().pid());
                """));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.out()).contains("tick1.xml: PASS", "hidden.xml: PASS");
    }

    /**
     * The grade, in {@link #shared}/many-scenes, of the correct solution on a --scenes folder that holds every
     * scene of the project's scenes folder, the hard scene giant-floor-1e16.xml and a scene of defaults
     * (defaults.xml): graded once, on first use, for the tests that each read the lines of their scenes.
     */
    private static synchronized CliRun correctOnManyScenes() throws IOException {
        if (correctOnManyScenes == null) {
            Path scenes = Files.createDirectories(shared.resolve("many-scenes").resolve("scenes"));
            try (Stream<Path> project = Files.list(Path.of("scenes"))) {
                for (Path scene : project.filter(f -> f.toString().endsWith(".xml")).toList()) {
                    Files.copy(scene, scenes.resolve(scene.getFileName()));
                }
            }
            Files.copy(Path.of("scenes/hard/giant-floor-1e16.xml"), scenes.resolve("giant-floor-1e16.xml"));
            Files.writeString(scenes.resolve("defaults.xml"), DEFAULTS_NESTING_AND_TWO_LIGHTS);
            correctOnManyScenes = grade(shared.resolve("many-scenes"), StudentSolution.correct(), "--scenes",
                    scenes.toString());
        }
        return correctOnManyScenes;
    }

    @Test
    void theCorrectSolutionPassesOnEverySceneOfTheProject() throws IOException {
        CliRun run = correctOnManyScenes();
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.out()).contains("scenes/hundred-spheres.xml: PASS", "scenes/no-ambient.xml: PASS")
                .doesNotContain("FAIL");
    }

    /** A scene that leaves most attributes to their defaults, nests a sphere in another and has two lights. */
    private static final String DEFAULTS_NESTING_AND_TWO_LIGHTS = """
                <scene>
                  <point-light x="2" y="2" colour="#FF0000"/>
                  <sphere z="5" colour="#00FF00">
                    <sphere x="1.5" y="0.5" z="6" radius="0.5" colour="#0000FF"/>
                  </sphere>
                  <point-light x="-1" y="3" z="1" colour="#FFFFFF" intensity="80"/>
                </scene>
                """;

    /** The starter SceneLoader must read what the reference loader reads, defaults included. */
    @Test
    void theStarterLoaderReadsDefaultsNestingAndTheLastLightAsTheReferenceDoes() throws IOException {
        CliRun run = correctOnManyScenes();
        assertThat(run.out()).as(run.transcript()).contains("scenes/defaults.xml: PASS");
    }

    @Test
    void aHitRejectedOnANegativeRootPassesTick1ButFailsWithTheCameraInsideASphere() throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("inside"));
        Files.copy(Path.of("scenes/hard/camera-inside-sphere.xml"), scenes.resolve("camera-inside-sphere.xml"));
        CliRun run = grade(HIT_REJECTED_ON_A_NEGATIVE_ROOT, "--scenes", scenes.toString());
        Variant mistake = Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT;
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(run.out()).as(run.transcript()).contains("tick1.xml: PASS",
                "camera-inside-sphere.xml: FAIL: " + HiddenVerdict.WRONG.words())
                .as("the scene is hidden: no catalogue entry").doesNotContain("closest: ", mistake.title());
        assertThat(run.out()).as("the handout's six steps find no hit from inside either: a correct answer")
                .doesNotContain("  behaviour: ", "  note: ");
    }

    @Test
    void aHitRejectedOnANegativeRootPassesTheCoursesScenesWithoutANote() throws IOException {
        CliRun run = grade(HIT_REJECTED_ON_A_NEGATIVE_ROOT);
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.out()).as(run.transcript()).contains(SubmissionGrader.CONGRATULATIONS).doesNotContain("Note:");
    }

    @Test
    void twoMistakesInTwoMethodsAreEachNamedByTheirModels() throws IOException {
        CliRun run = twoMistakes();
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(run.out().lines().filter(line -> line.startsWith("  behaviour: ")).toList()).as(run.transcript())
                .satisfiesExactly(
                        line -> assertThat(line).startsWith("  behaviour: your intersectionWith gives the answers of \""
                                + Variant.FAR_ROOT.title() + "\" on all "),
                        line -> assertThat(line).startsWith("  behaviour: your illuminate gives the answers of \""
                                + Variant.UNCLAMPED_N_DOT_L.title() + "\" on all "));
    }

    /**
     * A ray that passes within a hair of a sphere's outline is taken for a miss: no fixed or random
     * input grazes a sphere that closely, so the differing pixels' own rays are what show it.
     */
    @Test
    void aWrongImageWhoseMethodsPassEveryInputGetsTheCounterexampleOfADifferingPixel() throws IOException {
        CliRun run = grade(StudentSolution.correct().editSphere("if (discriminant < 0) {",
                "if (discriminant < 0.05) {"));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(run.out()).as(run.transcript()).doesNotContain("behave as ours")
                .containsPattern("  behaviour: your intersectionWith differs from ours at pixel \\(\\d+, \\d+\\) of "
                        + "tick1.xml, for the ray from O = \\(0, 0, 0\\) along D = .*, yours returns no hit; ours "
                        + "returns a hit at s = ");
    }

    /**
     * max(0, (R.V)^n) draws tick1.xml exactly as (R.V)^n does (n = 10 there), but where n is odd its
     * answers are not that mistake's: the image's match is never given as the cause.
     */
    @Test
    void anImageMatchingAMistakeTheAnswersRuleOutIsNotGivenAsItsCause() throws IOException {
        CliRun run = grade(StudentSolution.correct().editRenderer("Math.pow(Math.max(0, RdotV), n)",
                "Math.max(0, Math.pow(RdotV, n))"));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(run.out()).as(run.transcript()).contains("  behaviour: your illuminate differs from ours on ")
                .doesNotContain("likely cause", "is exactly the image of", "gives the answers of");
    }

    @Test
    void rootsAcceptedAtZeroPassTick1ButFailWhereASpherePassesThroughTheCamera() throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("through"));
        Files.copy(Path.of("src/test/resources/scenes/sphere-through-camera.xml"),
                scenes.resolve("sphere-through-camera.xml"));
        CliRun run = grade(ROOTS_ACCEPTED_AT_ZERO, "--scenes", scenes.toString());
        Variant mistake = Variant.ROOTS_ACCEPTED_AT_ZERO;
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        // The hidden scene says only its fixed words; what a ray from a sphere's surface does (seen in the public
        // run) is a note with the untested label.
        assertThat(run.out()).as(run.transcript()).contains("tick1.xml: PASS",
                "sphere-through-camera.xml: FAIL: " + HiddenVerdict.WRONG.words(),
                "  note: a mistake not tested by the course's scenes: for a ray that "
                        + "starts on a sphere's surface")
                .as("the scene is hidden: no catalogue entry for its image").doesNotContain("closest: ");
        assertThat(run.out()).as("the note names the model every answer of the public run's fits")
                .contains("every answer of yours is that of \"" + mistake.title() + "\"");
    }

    /**
     * The grade, in {@link #shared}/two-mistakes, of {@link #TWO_MISTAKES}, which fails both scenes: graded once,
     * on first use, for the tests that read what it printed and wrote.
     */
    private static synchronized CliRun twoMistakes() throws IOException {
        if (twoMistakes == null) {
            twoMistakes = grade(shared.resolve("two-mistakes"), TWO_MISTAKES);
        }
        return twoMistakes;
    }

    @Test
    void aFailingSceneLeavesItsHeatMapWhereTheReportSays() throws IOException {
        CliRun run = twoMistakes();
        Path report = shared.resolve("two-mistakes").resolve("report");
        Path heatMap = report.resolve("1-tick1-diff.png");
        assertThat(run.out()).as(run.transcript()).contains("heat map: " + heatMap);
        assertThat(heatMap).exists();
        assertThat(report.resolve("1-tick1-yours.png")).exists();
    }

    @Test
    void aFailingSceneWhoseImagesCannotBeWrittenExitsThreeWithOneLineSayingWhy() throws IOException {
        java.nio.file.Files.writeString(dir.resolve("report"), "a file where the report folder should go");
        CliRun run = grade(StudentSolution.correct().editRenderer(DIFFUSE, "k_d * NdotL"));
        assertThat(run.status()).as(run.transcript()).isEqualTo(3);
        assertThat(run.out()).contains("FAILED");
        assertThat(SandboxWarnings.stripped(run.err()).lines()).as(run.err()).isNotEmpty()
                .allMatch(line -> line.startsWith("tick1 grade: ") && line.contains("exists and is not a folder"));
    }

    @Test
    void codeThatDoesNotCompileIsReportedWithTheStudentsFileAndLine() throws IOException {
        CliRun run = grade(StudentSolution.correct().editSphere(NEAR_ROOT, "double s = s1 > 0 ? s1 : s2"));
        Path sphere = dir.resolve("student").resolve("Sphere.java");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(run.out()).startsWith("FAILED: the code does not compile (1 error):")
                .contains(sphere + ":" + StudentSolution.sphereLineOf(NEAR_ROOT) + ":")
                .contains("error: ';' expected")
                .doesNotContain("PASS", SubmissionGrader.CONGRATULATIONS);
    }

    @Test
    void systemExitInTheStudentsCodeIsReportedNotInherited() throws IOException {
        CliRun run = grade(StudentSolution.correct().editRenderer("return image;", "System.exit(0); return image;"));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(run.out()).contains("tick1.xml: FAIL: the program ended while rendering this scene, with exit "
                + "status 0 (does the code call System.exit?)");
    }

    @Test
    void aMissingStudentFileIsOneLineAndExitTwo() {
        CliRun run = CliRun.of("grade", "--sphere", dir.resolve("nope.java").toString(), "--renderer",
                dir.resolve("Renderer.java").toString());
        assertThat(run.status()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err()).isEqualTo("tick1 grade: " + dir.resolve("nope.java") + ": no such file"
                + System.lineSeparator());
    }

    @Test
    void aScenesFolderWithoutScenesIsOneLineAndExitTwo() throws IOException {
        Files.createDirectories(dir.resolve("empty"));
        CliRun run = grade(StudentSolution.correct(), "--scenes", dir.resolve("empty").toString());
        assertThat(run.status()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).hasSize(1);
        assertThat(run.err()).contains("no *.xml scene files");
    }

    @Test
    void aScenesFolderThatHoldsWhatTheRunsNeedIsRefusedInOneLine() throws IOException {
        CliRun run = grade(StudentSolution.correct(), "--scenes", "/usr");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err()).as("what grade said").isEqualTo("tick1 grade: /usr: the runs need "
                + Path.of(System.getProperty("java.home")).toRealPath() + ", so tick1 cannot hide this folder's "
                + "scenes from the student's code without stopping every run: give the scenes a folder of their own"
                + System.lineSeparator());
    }

    @Test
    void aFileInAnotherPackageFailsWithOneLineNamingThePackageTheTesterNeeds() throws IOException {
        CliRun run = grade(StudentSolution.correct().editSphere("package gfx.tick1;", "package tick1;"));
        Path sphere = dir.resolve("student").resolve("Sphere.java");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(run.out()).isEqualTo("FAILED: " + sphere + ": the tester needs the file in package gfx.tick1 (its "
                + "first line \"package gfx.tick1;\", as in the starter code), but it declares package tick1"
                + System.lineSeparator());
    }

    @Test
    void aFileThatIsNotUtf8IsNamedWithItsLineColumnAndByte() throws IOException {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        String renderer = Files.readString(files[1]);
        List<String> lines = renderer.lines().toList();
        int line = lines.indexOf(lines.stream().filter(l -> l.contains("// The colour")).findFirst().orElseThrow()) + 1;
        Files.write(files[1], renderer.replace("// The colour", "// Th\u00e9 colour")
                .getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
        CliRun run = CliRun.of("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--width", "16", "--height", "12");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err()).isEqualTo("tick1 grade: " + files[1] + ":" + line + ":"
                + (lines.get(line - 1).indexOf("// The") + 6) + ": not UTF-8 text: byte 0xE9 is "
                + "not part of a UTF-8 character; save the file as UTF-8" + System.lineSeparator());
    }

    @Test
    void theReportFolderShowsOnlyThisGradesImages() throws IOException {
        CliRun run = correctOnTheCoursesScenes();
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        try (Stream<Path> files = Files.list(shared.resolve("courses-scenes").resolve("report"))) {
            assertThat(files.map(f -> f.getFileName().toString())).containsExactly("notes.txt");
        }
    }

    @Test
    void aFailingHiddenSceneIsFixedWordsWithoutFiguresDiagnosisOrImages() throws IOException {
        CliRun run = twoMistakes();
        String hidden = run.out().substring(run.out().indexOf("hidden.xml: "));
        assertThat(hidden).as(run.transcript()).startsWith("hidden.xml: FAIL: "
                + HiddenVerdict.WRONG.words() + System.lineSeparator() + "FAILED: ");
        try (Stream<Path> files = Files.list(shared.resolve("two-mistakes").resolve("report"))) {
            assertThat(files.map(f -> f.getFileName().toString())).allMatch(name -> name.startsWith("1-tick1-"));
        }
    }

    @Test
    void theHandoutsFormulaPassesAHardHiddenSceneWhoseReportSaysOnlyPass() throws IOException {
        CliRun run = correctOnManyScenes();
        assertThat(run.out().lines()).as("which reference it matched is the code's to choose: not said")
                .anyMatch(line -> line.endsWith("/giant-floor-1e16.xml: " + HiddenVerdict.PASS.words()));
    }

    @Test
    void anOrganiserCanDemandTheRobustReference() throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("hard"));
        Files.copy(Path.of("scenes/hard/giant-floor-1e16.xml"), scenes.resolve("giant-floor-1e16.xml"));
        CliRun run = grade(StudentSolution.correct(), "--scenes", scenes.toString(), "--reference", "robust");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(run.out()).contains("giant-floor-1e16.xml: FAIL");
    }

    /**
     * The grade, in {@link #shared}/no-sandbox, of {@link #TWO_MISTAKES} with --no-sandbox: graded once, on first
     * use, for the tests that read what it printed and wrote.
     */
    private static synchronized CliRun twoMistakesWithoutTheSandbox() throws IOException {
        if (twoMistakesWithoutTheSandbox == null) {
            twoMistakesWithoutTheSandbox = grade(shared.resolve("no-sandbox"), TWO_MISTAKES, "--no-sandbox");
        }
        return twoMistakesWithoutTheSandbox;
    }

    /** What {@code run} printed, with {@code folder} (which holds its student's files and report) as FOLDER. */
    private static String outFrom(Path folder, CliRun run) {
        return run.out().replace(folder.toString(), "FOLDER");
    }

    @Test
    void withoutTheSandboxTheGradeWarnsAndStillGrades() throws IOException {
        CliRun run = twoMistakesWithoutTheSandbox();
        assertThat(run.err().lines()).as(run.transcript()).singleElement().asString()
                .startsWith("tick1 grade: warning: --no-sandbox: the student's code runs with your permissions")
                .as("the one line says what still limits the code").contains("limited only in time", "heap");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(outFrom(shared.resolve("no-sandbox"), run)).as("the report, to the word as the sandbox's grade's")
                .isEqualTo(outFrom(shared.resolve("two-mistakes"), twoMistakes()));
    }

    /** A file as a Windows editor may save it: a UTF-8 byte-order mark, then CRLF line ends. */
    private static String savedOnWindows(String source) {
        return "\uFEFF" + source.replace("\r\n", "\n").replace("\n", "\r\n");
    }

    /**
     * A solution with mistakes, as a student on Windows keeps it (saved by a Windows editor, in a folder
     * whose name has spaces and a letter beyond ASCII), is graded as the same files saved plainly, to
     * the word: with the sandbox where it can be made, and with --no-sandbox anywhere (the plain files' grades
     * are {@link #twoMistakes} and {@link #twoMistakesWithoutTheSandbox}).
     */
    @org.junit.jupiter.params.ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.ValueSource(strings = {"in the sandbox", "--no-sandbox"})
    void aSolutionSavedOnWindowsInAFolderNamedWithSpacesAndAnEIsGradedAsThePlainOne(String how)
            throws IOException, InterruptedException {
        gfx.tick1.FileNames.assumeTheyCanHold("Zoë");
        boolean sandboxed = !how.startsWith("--");
        if (sandboxed) {
            try {
                gfx.tick1.command.shared.grader.sandbox.Sandbox.confined();
            } catch (gfx.tick1.command.shared.grader.sandbox.Sandbox.Unavailable e) {
                org.junit.jupiter.api.Assumptions.abort("the sandbox cannot be made here: " + e.getMessage());
            }
        }
        Path plain = shared.resolve(sandboxed ? "two-mistakes" : "no-sandbox");
        Path windows = dir.resolve("Tick 1 (copy) Zoë");
        StudentSolution saved = new StudentSolution(savedOnWindows(TWO_MISTAKES.sphere()),
                savedOnWindows(TWO_MISTAKES.renderer()));
        assertThat(saved.sphere()).startsWith("\uFEFF").contains("\r\n");
        String[] options = sandboxed ? new String[0] : new String[] {"--no-sandbox"};
        CliRun asPlain = sandboxed ? twoMistakes() : twoMistakesWithoutTheSandbox();
        CliRun asSaved = grade(windows, saved, options);
        assertThat(asPlain.status()).as(asPlain.transcript()).isEqualTo(GradeCommand.EXIT_FAIL);
        assertThat(asPlain.out()).as(asPlain.transcript()).contains("tick1.xml: FAIL");
        assertThat(asSaved.status()).as(asSaved.transcript()).isEqualTo(asPlain.status());
        assertThat(outFrom(windows, asSaved)).as(asSaved.transcript()).isEqualTo(outFrom(plain, asPlain));
        assertThat(Files.list(windows.resolve("report")).map(file -> file.getFileName().toString()).sorted().toList())
                .as("the images of the failing scene, in the report folder of that name")
                .isEqualTo(Files.list(plain.resolve("report")).map(file -> file.getFileName().toString()).sorted()
                        .toList()).isNotEmpty();
    }

    @Test
    void withoutBubblewrapTheGradeRefusesInOneLineNamingThePackage() throws IOException, InterruptedException {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        // The missing bwrap is named to a tick1 in a JVM of its own, so that no other test's sandbox is affected.
        CliRun run = CliRun.inJvm(dir, List.of("-Dtick1.grade.bwrap=" + dir.resolve("no-bwrap-here")), "grade",
                "--sphere", files[0].toString(), "--renderer", files[1].toString(), "--report",
                dir.resolve("report").toString(), "--width", "160", "--height", "120");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.out()).isEmpty();
        assertThat(run.err().lines()).singleElement().asString().startsWith("tick1 grade: ")
                .contains("bubblewrap is not installed", "install the bubblewrap package", "--no-sandbox");
    }

    @Test
    void withoutBubblewrapACohortIsNotToldOfTheOptionItRefuses() throws IOException, InterruptedException {
        // A Moodle download's folder: "Full Name_participant id_assignsubmission_file_" (mod/assign, Moodle 4.x).
        StudentSolution.correct().writeTo(dir.resolve("download").resolve("Ann Lee_101_assignsubmission_file_"));
        CliRun run = CliRun.inJvm(dir, List.of("-Dtick1.grade.bwrap=" + dir.resolve("no-bwrap-here")), "grade",
                "--submissions", dir.resolve("download").toString(), "--report", dir.resolve("cohort").toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).singleElement().asString().contains("install the bubblewrap package")
                .as("--submissions refuses --no-sandbox, so it is not offered").doesNotContain("--no-sandbox");
    }

    @Test
    void offLinuxTheGradeSaysTheSandboxNeedsLinuxAndOffersTheOptionNotAPackage()
            throws IOException, InterruptedException {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        CliRun run = CliRun.inJvm(dir, List.of("-Dos.name=Mac OS X"), "grade", "--sphere", files[0].toString(),
                "--renderer", files[1].toString(), "--report", dir.resolve("report").toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).singleElement().asString()
                .contains("the sandbox needs Linux (this is Mac OS X)", "--no-sandbox").doesNotContain("apt-get");
    }

    /** In a container or a chroot bubblewrap is there but the kernel gives it no namespaces: installing is no cure. */
    @Test
    void whereTheKernelRefusesNamespacesTheGradeSaysSoInOneLineNotThatBubblewrapIsMissing()
            throws IOException, InterruptedException {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        // The refusing bwrap is named to a tick1 in a JVM of its own, so that no other test's sandbox is affected.
        CliRun run = CliRun.inJvm(dir, List.of("-Dtick1.grade.bwrap=" + RefusedNamespaces.bwrap(dir)), "grade",
                "--sphere", files[0].toString(), "--renderer", files[1].toString(), "--report",
                dir.resolve("report").toString(), "--width", "160", "--height", "120");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).singleElement().asString().startsWith("tick1 grade: ")
                .contains(RefusedNamespaces.WHAT_BWRAP_SAYS, "user namespaces", "--no-sandbox")
                .doesNotContain("install the bubblewrap package");
    }

    @Test
    void swappedFilesAreKnownByTheirClassGradedTheRightWayRoundAndSaidSo() throws IOException {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        List<String> args = new java.util.ArrayList<>(List.of("grade", "--sphere", files[1].toString(),
                "--renderer", files[0].toString(), "--report", dir.resolve("report").toString()));
        args.addAll(List.of(SMALL));
        CliRun run = CliRun.of(args.toArray(String[]::new));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(SandboxWarnings.stripped(run.err())).isEqualTo("tick1 grade: note: " + files[1]
                + " declares class Renderer and " + files[0]
                + " class Sphere: graded the other way round" + System.lineSeparator());
    }

    @Test
    void aFolderGivenAsAFileIsNamedWithWhatTheOptionWants() throws IOException {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        CliRun run = CliRun.of("grade", "--sphere", dir.toString(), "--renderer", files[1].toString());
        assertThat(run.status()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err()).isEqualTo("tick1 grade: " + dir + ": a folder, not a file: --sphere wants the "
                + "student's Sphere.java" + System.lineSeparator());
    }

    @Test
    void neitherOneStudentNorACohortIsOneLineSayingWhatToGive() {
        CliRun run = CliRun.of("grade");
        assertThat(run.status()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines().findFirst()).hasValueSatisfying(line -> assertThat(line)
                .contains("give --sphere and --renderer (one student), or --submissions (a cohort)"));
    }

    @Test
    void oneFileOfTwoIsOneLineNamingTheOther() throws IOException {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        CliRun run = CliRun.of("grade", "--sphere", files[0].toString());
        assertThat(run.status()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines().findFirst()).hasValueSatisfying(line -> assertThat(line)
                .contains("--renderer"));
    }

    @Test
    void oneStudentAndACohortAtOnceAreRefused() throws IOException {
        Path[] files = StudentSolution.correct().writeTo(dir.resolve("student"));
        CliRun run = CliRun.of("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--submissions", dir.toString());
        assertThat(run.status()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines().findFirst()).hasValueSatisfying(line -> assertThat(line)
                .contains("--submissions", "--sphere"));
    }

    @Test
    void aDownloadWithNoSubmissionsIsOneLineExitTwoAndWritesNothing() throws IOException {
        Path download = Files.createDirectory(dir.resolve("download"));
        Path report = dir.resolve("report");

        CliRun run = CliRun.of("grade", "--submissions", download.toString(), "--report", report.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines().filter(line -> !line.startsWith("tick1 grade: warning: ")))
                .as(run.transcript()).singleElement().asString().contains(download + ": no submissions");
        assertThat(run.out()).as("standard output").isEmpty();
        assertThat(report).as("the report folder").doesNotExist();
    }

    @Test
    void theDownloadsParentFolderIsOneLineExitTwoAndWritesNothing() throws IOException {
        Path parent = Files.createDirectory(dir.resolve("Downloads"));
        Files.write(parent.resolve("Tick 1.zip"), new byte[] {'P', 'K', 5, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
            0, 0, 0, 0, 0});
        Path report = parent.resolve("report");

        CliRun run = CliRun.of("grade", "--submissions", parent.toString(), "--report", report.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines().filter(line -> !line.startsWith("tick1 grade: warning: ")))
                .as(run.transcript()).singleElement().asString().contains(parent.resolve("Tick 1.zip").toString());
        assertThat(report).as("the report folder").doesNotExist();
    }

    @Test
    void aCohortIsNeverGradedWithoutTheSandbox() throws IOException {
        Path download = Files.createDirectory(dir.resolve("download"));
        CliRun run = CliRun.of("grade", "--submissions", download.toString(), "--report",
                dir.resolve("report").toString(), "--no-sandbox");
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).as(run.transcript()).singleElement().asString()
                .contains("--submissions never runs students' code without the sandbox");
        assertThat(dir.resolve("report")).as("the report folder").doesNotExist();
    }
}
