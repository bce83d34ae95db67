package gfx.tick1.grade;

import gfx.tick1.cli.ExitStatus;
import gfx.tick1.diagnose.Diagnoser;
import gfx.tick1.diagnose.Diagnosis;
import gfx.tick1.grade.StudentProcess.Outcome;
import gfx.tick1.image.ImageDifference;
import gfx.tick1.image.PngOutput;
import gfx.tick1.io.IoErrors;
import gfx.tick1.render.ReferenceRenderer;
import gfx.tick1.scene.BundledScenes;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.SceneException;
import gfx.tick1.scene.SceneLoader;
import gfx.tick1.starter.StarterKit;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code tick1 grade}: the course's tester, with reasons. Compiles a student's two files against
 * the starter code, renders the grading scenes with them in a separate JVM, and compares each
 * image with the reference render.
 */
@Command(name = "grade",
        description = {
            "Grades a student's Sphere.java and Renderer.java as the course's tester does: compiles them with the "
                    + "starter code (see tick1 starter), renders tick1.xml and a hidden scene (or the scenes given) "
                    + "with them, and compares each image with the reference render, pixel for pixel. Compiling and "
                    + "rendering run in a separate Java process inside a bubblewrap sandbox, with time, memory and "
                    + "process limits. A failing scene is explained: the difference figures, the closest entry of "
                    + "the diagnose catalogue, and a heat map (not for hidden scenes).",
            "Trust: inside the sandbox the student's code sees no file of yours but the scenes, has no network and "
                    + "cannot outlive the grade. It needs Linux and the bubblewrap package; --no-sandbox runs the "
                    + "code with your permissions instead."})
public final class GradeCommand implements Callable<Integer> {

    @ExitStatus("the code passed: every scene matches pixel for pixel")
    public static final int EXIT_PASS = 0;
    @ExitStatus("the code failed: it does not compile, crashed, ran out of time or memory, or an image is wrong")
    public static final int EXIT_FAIL = 1;
    @ExitStatus("the command line is wrong, a file given cannot be read, or the sandbox cannot be made")
    public static final int EXIT_USAGE = 2;
    @ExitStatus("a scene failed and its images could not be written to the report folder")
    public static final int EXIT_CANNOT_WRITE = 3;

    /** The course tester's own words for a pass. */
    public static final String CONGRATULATIONS = "Congratulations! Your code passed the tester.";

    @Spec
    private CommandSpec spec;

    @Option(names = "--sphere", paramLabel = "Sphere.java", required = true, description = "The student's Sphere.java.")
    private Path sphere;

    @Option(names = "--renderer", paramLabel = "Renderer.java", required = true,
            description = "The student's Renderer.java.")
    private Path renderer;

    @Option(names = "--scenes", paramLabel = "DIR",
            description = "Grade on tick1.xml and every *.xml in DIR instead of tick1.xml and the built-in hidden "
                    + "scene. The scenes of DIR are hidden: the report never quotes them and writes no images of them.")
    private Path scenesFolder;

    @Option(names = "--report", paramLabel = "DIR", defaultValue = "grade-report",
            description = "Where to write the images of failing scenes: the student's, the expected one and a heat "
                    + "map (default: ${DEFAULT-VALUE}).")
    private Path reportFolder;

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "60",
            description = "How long the student's code may take for all scenes together, Java's start included; "
                    + "compiling may take as long again (default: ${DEFAULT-VALUE}).")
    private double timeLimitSeconds;

    @Option(names = "--memory", paramLabel = "MiB", defaultValue = "512",
            description = "The student's code's heap limit (default: ${DEFAULT-VALUE}).")
    private int memoryMegabytes;

    @Option(names = "--width", paramLabel = "PIXELS", defaultValue = "640",
            description = "Image width (default: ${DEFAULT-VALUE}, as the course grades; smaller is quicker).")
    private int width;

    @Option(names = "--height", paramLabel = "PIXELS", defaultValue = "480",
            description = "Image height (default: ${DEFAULT-VALUE}).")
    private int height;

    @Option(names = "--reference", paramLabel = "WHICH", defaultValue = "either",
            description = "Which reference image a scene must equal: handout (the handout's intersection formula in "
                    + "plain doubles), robust (tick1's own renderer, accurate where that formula is not) or either "
                    + "(default: ${DEFAULT-VALUE}). The two differ only on hard scenes, such as giant spheres.")
    private ReferenceChoice referenceChoice;

    @Option(names = "--no-sandbox",
            description = "Run the student's code without the sandbox, with your permissions, your files and the "
                    + "network: only for code you trust, or where bubblewrap cannot run.")
    private boolean noSandbox;

    /** The references a scene may match: {@code --reference}. */
    enum ReferenceChoice {
        handout, robust, either
    }

    /**
     * One grading scene: a name to report it by, its file, the scene as the reference reads it, and
     * whether it is hidden (its content must not reach the student: no expected image, no message
     * text of the student's code).
     */
    private record GradingScene(String name, Path file, Scene scene, boolean hidden) {
    }

    @Override
    public Integer call() throws IOException, InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        String usage = checkOptions();
        if (usage != null) {
            throw new ParameterException(spec.commandLine(), usage);
        }
        Sandbox sandbox;
        if (noSandbox) {
            err.println("tick1 grade: warning: --no-sandbox: the student's code runs with your permissions; it can "
                    + "read, change and send anything you can");
            sandbox = Sandbox.unconfined();
        } else {
            try {
                sandbox = Sandbox.confined();
            } catch (Sandbox.Unavailable e) {
                err.println("tick1 grade: " + e.getMessage() + ": install the " + Sandbox.PACKAGE
                        + " package (apt-get install " + Sandbox.PACKAGE + "), or give --no-sandbox to grade "
                        + "without a sandbox");
                return EXIT_USAGE;
            }
        }
        Path work = Files.createTempDirectory("tick1-grade");
        StudentProcess process = new StudentProcess(sandbox, work.resolve("harness"), memoryMegabytes);
        // Ctrl-C or SIGTERM: stop the student's process and delete the work folder, scenes and all.
        Thread cleanUp = new Thread(() -> {
            process.stop();
            reportUndeleted(WorkFolder.delete(work), err);
        });
        Runtime.getRuntime().addShutdownHook(cleanUp);
        try {
            return grade(work, sandbox, process, out, err);
        } finally {
            process.stop();
            reportUndeleted(WorkFolder.delete(work), err);
            try {
                Runtime.getRuntime().removeShutdownHook(cleanUp);
            } catch (IllegalStateException e) {
                // The JVM is shutting down: the hook runs (or ran) anyway.
            }
        }
    }

    private static void reportUndeleted(String problem, PrintWriter err) {
        if (problem != null) {
            err.println("tick1 grade: " + problem);
            err.flush();
        }
    }

    private String checkOptions() {
        if (!(timeLimitSeconds > 0 && timeLimitSeconds <= 3600)) {
            return "--time-limit " + timeLimitSeconds + ": must be more than 0 and at most 3600 seconds";
        }
        if (memoryMegabytes < 32 || memoryMegabytes > 65536) {
            return "--memory " + memoryMegabytes + ": must be from 32 to 65536 MiB";
        }
        if (width < 1 || width > 4096 || height < 1 || height > 4096) {
            return "--width and --height must be from 1 to 4096, not " + width + " x " + height;
        }
        return null;
    }

    private int grade(Path work, Sandbox sandbox, StudentProcess process, PrintWriter out, PrintWriter err)
            throws IOException, InterruptedException {
        List<GradingScene> scenes;
        String sphereCode, rendererCode;
        try {
            sandbox.checkReachable(work);
            scenes = gradingScenes(work);
            sphereCode = StudentFile.read(sphere);
            rendererCode = StudentFile.read(renderer);
            WorkFolder.removeEarlierReport(reportFolder);
        } catch (SceneException e) {
            err.println("tick1 grade: " + e.getMessage());
            return EXIT_USAGE;
        } catch (IOException e) {
            err.println("tick1 grade: " + IoErrors.describe(e));
            return EXIT_USAGE;
        }
        for (String problem : new String[] {StudentFile.packageProblem(sphere.toString(), sphereCode),
                StudentFile.packageProblem(renderer.toString(), rendererCode)}) {
            if (problem != null) {
                out.println("FAILED: " + problem);
                return EXIT_FAIL;
            }
        }

        Path sources = Files.createDirectory(work.resolve("sources"));
        Files.writeString(sources.resolve("Sphere.java"), sphereCode, StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("Renderer.java"), rendererCode, StandardCharsets.UTF_8);
        for (String given : StarterKit.GIVEN_CLASSES) {
            Files.writeString(sources.resolve(given + ".java"), StarterKit.source(given), StandardCharsets.UTF_8);
        }
        StudentProcess.writeHarness(Files.createDirectory(work.resolve("harness")));
        sandbox.share(work, false);
        Path compiledFolder = childFolder(work, "compiled", sandbox);

        StudentProcess.Compiled compiled = process.compile(sources, compiledFolder, sphere.toString(),
                renderer.toString(), timeLimit());
        if (compiled.failure() != null) {
            out.println("FAILED: the code could not be compiled: " + compiled.failure());
            return EXIT_FAIL;
        }
        if (!compiled.compiled()) {
            out.println("FAILED: the code does not compile (" + count(compiled.errors().size(), "error") + "):");
            compiled.errors().forEach(out::println);
            return EXIT_FAIL;
        }
        out.println("Compiled " + sphere + " and " + renderer + " with the starter code.");

        // The public scenes and the hidden ones run separately, so that what the student's code
        // prints while it has a hidden scene open is never shown.
        Path classes = compiledFolder.resolve(StudentHarness.CLASSES_FOLDER);
        long deadline = System.nanoTime() + timeLimit().toNanos();
        List<Outcome> outcomes = new ArrayList<>();
        String publicOutput = "";
        for (boolean hidden : new boolean[] {false, true}) {
            List<GradingScene> batch = scenes.stream().filter(scene -> scene.hidden() == hidden).toList();
            if (batch.isEmpty()) {
                continue;
            }
            Duration left = Duration.ofNanos(deadline - System.nanoTime());
            if (left.toMillis() < 1) {
                batch.forEach(scene -> outcomes.add(new Outcome.Failed(
                        "not rendered: the time limit was used up by the earlier scenes")));
                continue;
            }
            String folder = hidden ? "hidden" : "public";
            StudentProcess.Result result = process.render(classes, work.resolve(folder + "-scenes"),
                    sceneFiles(batch.size()), childFolder(work, folder + "-output", sandbox), width, height, left,
                    timeLimit());
            outcomes.addAll(result.outcomes());
            if (!hidden) {
                publicOutput = result.outputTail();
            }
        }

        Map<String, String> sourceTexts = new HashMap<>();
        sourceTexts.put("Sphere.java", sphereCode);
        sourceTexts.put("Renderer.java", rendererCode);
        StarterKit.GIVEN_CLASSES.forEach(given -> sourceTexts.put(given + ".java", StarterKit.source(given)));
        HiddenScenes hiddenScenes = new HiddenScenes(sourceTexts, classes);
        int failures = 0;
        boolean crashed = false;
        for (int i = 0; i < scenes.size(); i++) {
            GradingScene scene = scenes.get(i);
            Outcome outcome = outcomes.get(i);
            if (outcome instanceof Outcome.Failed failed) {
                failures++;
                crashed = true;
                String reason = scene.hidden() ? hiddenScenes.withoutMessages(failed.reason()) : failed.reason();
                out.println(scene.name() + ": FAIL: " + indent(reason));
            } else if (!checkImage(i + 1, scene, ((Outcome.Rendered) outcome).image(), out, err)) {
                failures++;
            }
        }
        if (crashed && !publicOutput.isBlank()) {
            out.println("The last lines the code printed (while rendering the scenes that are not hidden):");
            publicOutput.lines().skip(Math.max(0, publicOutput.lines().count() - 5))
                    .forEach(line -> out.println("  " + line));
        }
        if (failures > 0) {
            out.println("FAILED: " + failures + " of " + count(scenes.size(), "scene") + " wrong.");
            return reportUnwritable ? EXIT_CANNOT_WRITE : EXIT_FAIL;
        }
        out.println(CONGRATULATIONS);
        return EXIT_PASS;
    }

    private Duration timeLimit() {
        return Duration.ofMillis(Math.round(timeLimitSeconds * 1000));
    }

    /** An empty folder for the student's process to write in. */
    private static Path childFolder(Path work, String name, Sandbox sandbox) throws IOException {
        Path folder = Files.createDirectory(work.resolve(name));
        sandbox.share(folder, true);
        return folder;
    }

    /** The names the scenes of a batch have inside the sandbox: 0.xml, 1.xml, ... */
    private static List<String> sceneFiles(int count) {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            names.add(i + ".xml");
        }
        return names;
    }

    /** Set when a failing scene's images could not be written to the report folder: exit status 3. */
    private boolean reportUnwritable;

    /**
     * Compares one student image with the references --reference allows; explains the difference
     * when it matches none, and, for a scene that is not hidden, writes the heat map.
     */
    private boolean checkImage(int number, GradingScene grading, BufferedImage image, PrintWriter out, PrintWriter err)
            throws IOException {
        BufferedImage handout = referenceChoice == ReferenceChoice.robust ? null
                : new ReferenceRenderer(width, height, Intersection.HANDOUT).render(grading.scene());
        BufferedImage robust = referenceChoice == ReferenceChoice.handout ? null
                : new ReferenceRenderer(width, height, Intersection.ROBUST).render(grading.scene());
        ImageDifference toHandout = handout == null ? null : ImageDifference.between(handout, image);
        ImageDifference toRobust = robust == null ? null : ImageDifference.between(robust, image);
        boolean referencesAgree = handout != null && robust != null
                && ImageDifference.between(handout, robust).differingPixels() == 0;
        if (toHandout != null && toHandout.differingPixels() == 0 || toRobust != null && toRobust.differingPixels() == 0) {
            String which = "the reference", other = "";
            if (handout != null && robust != null && !referencesAgree) {
                boolean handoutMatched = toHandout.differingPixels() == 0;
                which = handoutMatched ? "the handout-arithmetic reference" : "the robust reference";
                other = "; the " + (handoutMatched ? "robust" : "handout-arithmetic") + " reference differs on this scene";
            }
            out.println(grading.name() + ": PASS (identical to " + which + ", "
                    + (toHandout != null ? toHandout : toRobust).totalPixels() + " pixels" + other + ")");
            return true;
        }
        // Explain against the closer reference.
        boolean againstHandout = toRobust == null
                || toHandout != null && toHandout.differingPixels() < toRobust.differingPixels();
        ImageDifference difference = againstHandout ? toHandout : toRobust;
        BufferedImage expected = againstHandout ? handout : robust;
        out.println(grading.name() + ": FAIL: " + difference.summary());
        if (handout != null && robust != null && !referencesAgree) {
            out.println("  (compared with the " + (againstHandout ? "handout-arithmetic" : "robust")
                    + " reference, the closer of the two, which differ on this scene)");
        }
        double[] mean = difference.meanPerChannel();
        out.printf("  mean difference R %.3f, G %.3f, B %.3f levels; PSNR %.2f dB%n", mean[0], mean[1], mean[2],
                difference.psnr());
        Diagnosis diagnosis = new Diagnoser().diagnose(image, grading.scene());
        diagnosis.report().forEach(line -> out.println("  " + line));
        if (grading.hidden()) {
            out.println("  (a hidden scene: no images are written for it)");
            return false;
        }
        String stem = number + "-" + grading.name().replaceAll("[^A-Za-z0-9._-]", "_").replaceAll("\\.xml$", "");
        try {
            Files.createDirectories(reportFolder);
            PngOutput.write(difference.heatMapWithLegend(), reportFolder.resolve(stem + "-diff.png"));
            PngOutput.write(image, reportFolder.resolve(stem + "-yours.png"));
            PngOutput.write(expected, reportFolder.resolve(stem + "-expected.png"));
            out.println("  heat map: " + reportFolder.resolve(stem + "-diff.png") + " (beside it: " + stem
                    + "-yours.png and " + stem + "-expected.png)");
        } catch (IOException e) {
            err.println("tick1 grade: " + reportFolder + ": cannot write the report images: " + IoErrors.describe(e));
            reportUnwritable = true;
        }
        return false;
    }

    /**
     * tick1.xml, then the hidden scene or the scenes of --scenes (all hidden), each checked by the
     * reference loader and copied into the work folder for the student's process: public ones to
     * public-scenes/, hidden ones to hidden-scenes/, as 0.xml, 1.xml, ... in order.
     */
    private List<GradingScene> gradingScenes(Path work) throws IOException {
        Path bundled = Files.createDirectory(work.resolve("bundled"));
        List<GradingScene> scenes = new ArrayList<>();
        scenes.add(load(BundledScenes.TICK1, BundledScenes.extract(BundledScenes.TICK1, bundled), false));
        if (scenesFolder == null) {
            scenes.add(load(BundledScenes.HIDDEN, BundledScenes.extract(BundledScenes.HIDDEN, bundled), true));
        } else {
            if (!Files.isDirectory(scenesFolder)) {
                throw new IOException(scenesFolder + ": not a folder (--scenes wants a folder of *.xml scenes)");
            }
            try (Stream<Path> files = Files.list(scenesFolder)) {
                List<Path> xml = files.filter(f -> f.toString().endsWith(".xml") && Files.isRegularFile(f))
                        .sorted(Comparator.comparing(Path::toString)).toList();
                if (xml.isEmpty()) {
                    throw new IOException(scenesFolder + ": no *.xml scene files in the folder");
                }
                for (Path file : xml) {
                    scenes.add(load(file.toString(), file, true));
                }
            }
        }
        for (boolean hidden : new boolean[] {false, true}) {
            Path folder = Files.createDirectory(work.resolve((hidden ? "hidden" : "public") + "-scenes"));
            int index = 0;
            for (GradingScene scene : scenes) {
                if (scene.hidden() == hidden) {
                    Files.copy(scene.file(), folder.resolve(index++ + ".xml"));
                }
            }
        }
        return scenes;
    }

    private static GradingScene load(String name, Path file, boolean hidden) {
        Scene scene = new SceneLoader(file, false).getScene();
        if (scene.getPointLight() == null) {
            // The handout's illuminate() starts with scene.getPointLight().getPosition().
            throw new SceneException(file + ": no <point-light>: the starter code needs one to grade with");
        }
        return new GradingScene(name, file, scene, hidden);
    }

    private static String indent(String text) {
        return text.replace("\n", "\n    ");
    }

    private static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }
}
