package gfx.tick1.grade;

import gfx.tick1.diagnose.Diagnoser;
import gfx.tick1.diagnose.Diagnosis;
import gfx.tick1.grade.StudentProcess.Outcome;
import gfx.tick1.image.ImageDifference;
import gfx.tick1.image.PngOutput;
import gfx.tick1.render.ReferenceRenderer;
import gfx.tick1.scene.BundledScenes;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.SceneException;
import gfx.tick1.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.MalformedInputException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
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
@Command(name = "grade", mixinStandardHelpOptions = true, sortOptions = false, usageHelpAutoWidth = true,
        description = {
            "Grades a student's Sphere.java and Renderer.java as the course's tester does: compiles them with the "
                    + "starter code (see tick1 starter), renders tick1.xml and a hidden scene (or the scenes given) "
                    + "in a separate Java process with a time and a memory limit, and compares each image with the "
                    + "reference render, pixel for pixel. A failing scene is explained: the difference figures, "
                    + "the closest entry of the diagnose catalogue, and a heat map.",
            "Trust: the student's code runs with your permissions (it can read and write your files). Grade "
                    + "untrusted code inside a container or a throw-away account."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:the code passed: every scene matches pixel for pixel",
            "1:the code failed: it does not compile, crashed, ran out of time or memory, or an image is wrong",
            "2:the command line is wrong, or a file given cannot be read",
            "3:a scene failed and its images could not be written to the report folder",
            "4:an internal error (a bug: please report it)"})
public final class GradeCommand implements Callable<Integer> {

    public static final int EXIT_PASS = 0;
    public static final int EXIT_FAIL = 1;
    public static final int EXIT_USAGE = 2;
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
                    + "scene.")
    private Path scenesFolder;

    @Option(names = "--report", paramLabel = "DIR", defaultValue = "grade-report",
            description = "Where to write the images of failing scenes: the student's, the expected one and a heat "
                    + "map (default: ${DEFAULT-VALUE}).")
    private Path reportFolder;

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "60",
            description = "How long the student's code may take for all scenes together, Java's start included "
                    + "(default: ${DEFAULT-VALUE}).")
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

    /** One grading scene: a name to report it by, its file, and the scene as the reference reads it. */
    private record GradingScene(String name, Path file, Scene scene) {
    }

    @Override
    public Integer call() throws IOException, InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        String usage = checkOptions();
        if (usage != null) {
            throw new ParameterException(spec.commandLine(), usage);
        }
        Path work = Files.createTempDirectory("tick1-grade");
        try {
            return grade(work, out, err);
        } finally {
            deleteRecursively(work);
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

    private int grade(Path work, PrintWriter out, PrintWriter err) throws IOException, InterruptedException {
        List<GradingScene> scenes;
        StudentCompiler.Result compiled;
        try {
            scenes = gradingScenes(work);
            compiled = new StudentCompiler().compile(sphere, renderer);
        } catch (SceneException | StudentCompiler.NoCompilerException e) {
            err.println("tick1 grade: " + e.getMessage());
            return EXIT_USAGE;
        } catch (IOException e) {
            err.println("tick1 grade: " + describe(e));
            return EXIT_USAGE;
        }

        if (!compiled.compiled()) {
            out.println("FAILED: the code does not compile (" + count(compiled.errors().size(), "error") + "):");
            compiled.errors().forEach(out::println);
            return EXIT_FAIL;
        }
        out.println("Compiled " + sphere + " and " + renderer + " with the starter code.");

        Path classes = work.resolve("classes");
        compiled.writeClasses(classes);
        Path run = Files.createDirectory(work.resolve("run"));
        StudentProcess.Result result = new StudentProcess(Duration.ofMillis(Math.round(timeLimitSeconds * 1000)),
                memoryMegabytes).render(classes, run, width, height, scenes.stream().map(GradingScene::file).toList());

        int failures = 0;
        boolean crashed = false;
        for (int i = 0; i < scenes.size(); i++) {
            Outcome outcome = result.outcomes().get(i);
            if (outcome instanceof Outcome.Failed failed) {
                failures++;
                crashed = true;
                out.println(scenes.get(i).name() + ": FAIL: " + indent(failed.reason()));
            } else if (!checkImage(i + 1, scenes.get(i), ((Outcome.Rendered) outcome).image(), out, err)) {
                failures++;
            }
        }
        if (crashed && !result.outputTail().isBlank()) {
            out.println("The last lines the code printed:");
            result.outputTail().lines().skip(Math.max(0, result.outputTail().lines().count() - 5))
                    .forEach(line -> out.println("  " + line));
        }
        if (failures > 0) {
            out.println("FAILED: " + failures + " of " + count(scenes.size(), "scene") + " wrong.");
            return reportUnwritable ? EXIT_CANNOT_WRITE : EXIT_FAIL;
        }
        out.println(CONGRATULATIONS);
        return EXIT_PASS;
    }

    /** Set when a failing scene's images could not be written to the report folder: exit status 3. */
    private boolean reportUnwritable;

    /** Compares one student image with the reference; explains and writes the heat map when they differ. */
    private boolean checkImage(int number, GradingScene grading, BufferedImage image, PrintWriter out, PrintWriter err)
            throws IOException {
        BufferedImage expected = new ReferenceRenderer(width, height).render(grading.scene());
        ImageDifference difference = ImageDifference.between(expected, image);
        if (difference.differingPixels() == 0) {
            out.println(grading.name() + ": PASS (identical to the reference, " + difference.totalPixels()
                    + " pixels)");
            return true;
        }
        out.println(grading.name() + ": FAIL: " + difference.summary());
        double[] mean = difference.meanPerChannel();
        out.printf("  mean difference R %.3f, G %.3f, B %.3f levels; PSNR %.2f dB%n", mean[0], mean[1], mean[2],
                difference.psnr());
        Diagnosis diagnosis = new Diagnoser().diagnose(image, grading.scene());
        diagnosis.report().forEach(line -> out.println("  " + line));
        String stem = number + "-" + grading.name().replaceAll("[^A-Za-z0-9._-]", "_").replaceAll("\\.xml$", "");
        try {
            Files.createDirectories(reportFolder);
            PngOutput.write(difference.heatMap(), reportFolder.resolve(stem + "-diff.png"));
            PngOutput.write(image, reportFolder.resolve(stem + "-yours.png"));
            PngOutput.write(expected, reportFolder.resolve(stem + "-expected.png"));
            out.println("  heat map: " + reportFolder.resolve(stem + "-diff.png") + " (beside it: " + stem
                    + "-yours.png and " + stem + "-expected.png)");
        } catch (IOException e) {
            err.println("tick1 grade: " + reportFolder + ": cannot write the report images: " + describe(e));
            reportUnwritable = true;
        }
        return false;
    }

    /** tick1.xml, then the hidden scene or the scenes of --scenes, each checked by the reference loader. */
    private List<GradingScene> gradingScenes(Path work) throws IOException {
        Path bundled = Files.createDirectory(work.resolve("scenes"));
        List<GradingScene> scenes = new ArrayList<>();
        if (scenesFolder == null) {
            for (String name : BundledScenes.GRADING) {
                scenes.add(load(name, BundledScenes.extract(name, bundled)));
            }
            return scenes;
        }
        scenes.add(load(BundledScenes.TICK1, BundledScenes.extract(BundledScenes.TICK1, bundled)));
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
                scenes.add(load(file.toString(), file));
            }
        }
        return scenes;
    }

    private static GradingScene load(String name, Path file) {
        Scene scene = new SceneLoader(file, false).getScene();
        if (scene.getPointLight() == null) {
            // The handout's illuminate() starts with scene.getPointLight().getPosition().
            throw new SceneException(file + ": no <point-light>: the starter code needs one to grade with");
        }
        return new GradingScene(name, file, scene);
    }

    private static String indent(String text) {
        return text.replace("\n", "\n    ");
    }

    private static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }

    private static String describe(IOException e) {
        if (e instanceof NoSuchFileException) {
            return e.getMessage() + ": no such file";
        }
        if (e instanceof MalformedInputException) {
            return "a student file is not UTF-8 text";
        }
        if (e instanceof java.nio.file.FileAlreadyExistsException) {
            return e.getMessage() + " exists and is not a folder";
        }
        if (e instanceof java.nio.file.AccessDeniedException) {
            return e.getMessage() + ": permission denied";
        }
        return e.getMessage();
    }

    private static void deleteRecursively(Path folder) throws IOException {
        try (Stream<Path> files = Files.walk(folder)) {
            files.sorted(Comparator.reverseOrder()).forEach(file -> {
                try {
                    Files.delete(file);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        }
    }
}
