package gfx.tick1.command.bench;

import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.engine.fast.FastRenderer;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.io.Counted;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.io.OnExit;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.render.SamplePattern;
import gfx.tick1.engine.render.TruthRenderer;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code tick1 bench}: every way of rendering side by side in one process, on the same scenes,
 * with the time each takes and how far its image is from the right one; then whole runs of the
 * program in fresh processes for start-up, scaling and end-to-end time. Writes report.md,
 * results.csv and speed-vs-error.png into one folder; the scenes it renders (tick1.xml and the
 * generated crowds) and the yardsticks' builds and images go to a temporary folder deleted on exit.
 * It needs nothing but the installed program: the course code's correct solution is tick1's own.
 */
@Command(name = "bench",
        description = {"Measures speed against accuracy for every renderer variant and writes a report "
                + "(report.md, results.csv, speed-vs-error.png).",
            "The report goes into the folder --out names (tick1-bench unless told otherwise). The yardsticks it "
                    + "compares tick1 with (the course's code, built from the starter kit and tick1's own solution, "
                    + "and a scalar C tracer where a C compiler is), the scenes it renders and their images are kept "
                    + "in a temporary folder, deleted when it ends."})
public final class BenchCommand implements Callable<Integer> {

    @ExitStatus("the report was written")
    public static final int EXIT_OK = 0;
    @ExitStatus("the report could not be written, or a timed run of tick1 failed")
    public static final int EXIT_CANNOT_WRITE = 3;

    @Spec
    private CommandSpec spec;

    @Option(names = "--quick", description = "Small frames, each whole run and each of one student's runs once, "
            + "and a cohort of 2: for CI, a check that everything runs and each goal is measured (coarsely), not a "
            + "measure of speed. The full run is for people.")
    private boolean quick;

    @Option(names = "--one-student", description = "Only the one-student section: one student's grade, diff and "
            + "VPL evaluation beside the course's bare compile-and-run, in fresh processes (5 runs each, or once with "
            + "--quick). Writes report.md alone.")
    private boolean oneStudent;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "tick1-bench",
            description = "The folder to write the report into, created if missing (default: ${DEFAULT-VALUE}, in the "
                    + "current folder).")
    private Path out;

    private PrintWriter log;

    /**
     * The files the runs read and write that are no part of the report: tick1.xml and the crowds (about 800 KB), the
     * yardsticks' builds, and the C tracer's image (6 MB for the full run).
     */
    private Path scenes;

    @Override
    public Integer call() {
        OnExit cleanUp = null;
        try {
            scenes = Files.createTempDirectory("tick1-bench-scenes");
            Path folder = scenes;
            cleanUp = OnExit.run("tick1-bench-clean-up", () -> deleteTree(folder));
            return run();
        } catch (IOException e) {
            spec.commandLine().getErr().println("tick1 bench: " + IoErrors.describe(e));
            return EXIT_CANNOT_WRITE;
        } finally {
            if (cleanUp != null) {
                cleanUp.now();
            }
        }
    }

    /** Deletes {@code folder} and what it holds, following no link; what cannot be deleted is left. */
    private static void deleteTree(Path folder) {
        try (Stream<Path> files = Files.walk(folder)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(file);
            }
        } catch (IOException e) {
            // Left in the temporary folder, where the system's own cleaning finds it.
        }
    }

    private int run() throws IOException {
        log = spec.commandLine().getOut();
        Files.createDirectories(out);
        BenchPlan plan = quick ? BenchPlan.QUICK : BenchPlan.FULL;
        int cores = Runtime.getRuntime().availableProcessors();
        if (oneStudent) {
            log.printf("tick1 bench --one-student%s: %s, Java %s%n", quick ? " --quick" : "",
                    Counted.of(cores, "core"), System.getProperty("java.version"));
            OneStudentSection.Measured student = oneStudent(plan, new ProcessRuns(plan.warmUpProcesses()));
            Files.writeString(out.resolve("report.md"), BenchReport.heading(quick, cores)
                    + OneStudentSection.markdown(student, quick), StandardCharsets.UTF_8);
            log.printf("Wrote %s%n", out.resolve("report.md"));
            return EXIT_OK;
        }

        Path tick1File = BundledScenes.extract(BundledScenes.TICK1, scenes);
        Scene tick1 = load(tick1File);

        List<Result> results = new ArrayList<>();
        log.printf("tick1 bench (%s): %s, Java %s%n", quick ? "quick" : "full", Counted.of(cores, "core"),
                System.getProperty("java.version"));

        BufferedImage truth = new TruthRenderer(plan.errorWidth(), plan.errorHeight()).render(tick1);
        BufferedImage manySamples = new FastRenderer(plan.errorWidth(), plan.errorHeight(),
                new SamplePattern(256)).render(tick1);
        for (RenderSetting setting : tick1Settings(cores)) {
            boolean antiAliased = setting.samples() > 1;
            results.add(measure(setting, "tick1.xml", tick1, plan.width(), plan.height(), plan,
                    antiAliased ? "256 samples" : "truth", antiAliased ? manySamples : truth));
        }
        for (int count : plan.crowds()) {
            Path file = scenes.resolve("crowd-" + count + ".xml");
            Files.writeString(file, CrowdScene.xml(count));
            Scene crowd = load(file);
            BufferedImage bruteForce = new FastRenderer(plan.errorWidth(), plan.errorHeight(), new SamplePattern(1),
                    FastRenderer.SphereSearch.BRUTE_FORCE, Intersection.DEFAULT).render(crowd);
            for (FastRenderer.SphereSearch search : new FastRenderer.SphereSearch[] {
                FastRenderer.SphereSearch.BRUTE_FORCE, FastRenderer.SphereSearch.BVH}) {
                RenderSetting setting = new RenderSetting(
                        search == FastRenderer.SphereSearch.BVH ? "BVH" : "brute force", 1, cores,
                        (s, w, h) -> new FastRenderer(w, h, new SamplePattern(1), search, Intersection.DEFAULT)
                                .render(s));
                // Brute force over 10,000 spheres takes seconds a frame: fewer runs for the crowds.
                results.add(measure(setting, file.getFileName().toString(), crowd, plan.crowdWidth(),
                        plan.crowdWidth() * 3 / 4, plan.withRuns(1, Math.min(plan.runs(), 3)), "brute force",
                        bruteForce));
            }
        }

        Map<String, String> png = pngEncoding(tick1, plan);
        ProcessRuns runs = new ProcessRuns(plan.warmUpProcesses());
        Whole whole = wholeRuns(runs, plan, tick1File, tick1);

        OneStudentSection.Measured student = oneStudent(plan, runs);

        BenchReport report = new BenchReport(quick, cores, results, png, runs.describe(), whole);
        report.write(out);
        Files.writeString(out.resolve("report.md"), OneStudentSection.markdown(student, quick),
                StandardCharsets.UTF_8, StandardOpenOption.APPEND);
        CohortTiming.Measured cohort = CohortSection.appendTo(out.resolve("report.md"), runs, plan.cohort(),
                Files.createDirectory(scenes.resolve("cohort")), log);
        Goals goals = new Goals(quick, plan, whole, cohort);
        Files.writeString(out.resolve("report.md"), goals.markdown(), StandardCharsets.UTF_8,
                StandardOpenOption.APPEND);
        goals.print(log);
        log.printf("Wrote %s, %s and %s%n", out.resolve("report.md"), out.resolve("results.csv"),
                out.resolve("speed-vs-error.png"));
        return EXIT_OK;
    }

    /** The one-student section, measured in a folder of its own and printed. */
    private OneStudentSection.Measured oneStudent(BenchPlan plan, ProcessRuns runs) throws IOException {
        log.println("one student: the bare pipeline, grade, diff and grade --format vpl in turn");
        log.flush();
        OneStudentSection.Measured student = OneStudentSection.measure(runs, plan.studentRuns(),
                Files.createDirectory(scenes.resolve("one-student")));
        OneStudentSection.print(student, log);
        return student;
    }

    /**
     * The render plan, in the order they run. The default comes first: everything the JIT learns
     * from the others (other intersection methods, the readable classes) only slows later code,
     * and a user's render runs the default alone.
     */
    private static List<RenderSetting> tick1Settings(int cores) {
        List<RenderSetting> renderSettings = new ArrayList<>();
        for (Intersection intersection : new Intersection[] {Intersection.ROBUST, Intersection.HANDOUT}) {
            for (int threads : new int[] {cores, 1}) {
                renderSettings.add(new RenderSetting("fast double, " + name(intersection), 1, threads,
                        (s, w, h) -> new FastRenderer(w, h, new SamplePattern(1), intersection).render(s)));
            }
        }
        for (int samples : new int[] {4, 16}) {
            renderSettings.add(new RenderSetting("fast double, robust, " + samples + " samples", samples, cores,
                    (s, w, h) -> new FastRenderer(w, h, new SamplePattern(samples)).render(s)));
        }
        renderSettings.add(new RenderSetting("float, handout formula", 1, cores,
                (s, w, h) -> new FloatRenderer(w, h, FloatRenderer.Formula.HANDOUT).render(s)));
        renderSettings.add(new RenderSetting("float, robust", 1, cores,
                (s, w, h) -> new FloatRenderer(w, h, FloatRenderer.Formula.ROBUST).render(s)));
        renderSettings.add(new RenderSetting("readable Renderer, robust", 1, cores,
                (s, w, h) -> new ReferenceRenderer(w, h).render(s)));
        renderSettings.add(new RenderSetting("readable Renderer, handout formula", 1, 1,
                (s, w, h) -> new ReferenceRenderer(w, h, Intersection.HANDOUT).render(s)));
        return renderSettings;
    }

    private static String name(Intersection intersection) {
        return intersection == Intersection.HANDOUT ? "handout formula" : "robust (default)";
    }

    private Result measure(RenderSetting setting, String sceneName, Scene scene, int width, int height,
            BenchPlan plan, String errorAgainst, BufferedImage reference) {
        Timing timing = Timing.of(() -> setting.frame().render(scene, width, height), setting.threads(),
                plan.warmups(), plan.runs());
        BufferedImage small = setting.frame().render(scene, reference.getWidth(), reference.getHeight());
        Result result = new Result(setting.name(), sceneName, width, height, setting.samples(), setting.threads(),
                timing, errorAgainst, ImageDifference.between(reference, small), reference.getWidth(),
                reference.getHeight());
        log.printf("  %-45s %-16s %-11s %9.1f ms %8.1f Mrays/s  max error %s%n", setting.name(), sceneName,
                Counted.of(setting.threads(), "thread"), timing.median(), result.megaRaysPerSecond(),
                Counted.of(result.error().maxDifference(), "level"));
        log.flush();
        return result;
    }

    /** ImageIO's PNG writer at several deflate levels on the benchmark's largest tick1 frame: time and size. */
    private Map<String, String> pngEncoding(Scene scene, BenchPlan plan) throws IOException {
        BufferedImage frame = new FastRenderer(plan.width(), plan.height(), new SamplePattern(1)).render(scene);
        Map<String, String> rows = new LinkedHashMap<>();
        Map<String, Encoder> encoders = new LinkedHashMap<>();
        encoders.put("ImageIO, deflate level 1", (image, stream) -> PngOutput.write(image, stream, 1));
        encoders.put("ImageIO, deflate level " + PngOutput.DEFLATE_LEVEL + " (tick1's setting)", PngOutput::write);
        encoders.put("ImageIO, defaults (deflate level 4)", (image, stream) -> ImageIO.write(image, "png", stream));
        encoders.put("ImageIO, deflate level 9", (image, stream) -> PngOutput.write(image, stream, 9));
        for (Map.Entry<String, Encoder> encoder : encoders.entrySet()) {
            int[] size = new int[1];
            Timing timing = Timing.of(() -> {
                ByteArrayOutputStream bytes = new ByteArrayOutputStream();
                try {
                    encoder.getValue().encode(frame, bytes);
                } catch (IOException e) {
                    throw new IllegalStateException(e);
                }
                size[0] = bytes.size();
                return null;
            }, Runtime.getRuntime().availableProcessors(), plan.warmups(), plan.runs());
            rows.put(encoder.getKey(), String.format("%.1f ms | %,d bytes", timing.median(), size[0]));
            log.printf("  PNG %-45s %8.1f ms %,12d bytes%n", encoder.getKey(), timing.median(), size[0]);
        }
        return rows;
    }

    private interface Encoder {
        void encode(BufferedImage image, ByteArrayOutputStream out) throws IOException;
    }

    /**
     * Whole runs in fresh processes. {@code courseCode} and {@code scalarC} are the yardsticks run
     * in turn with tick1's runs beside them ({@code startup} and {@code endToEnd}), or null with
     * the reason in {@code courseCodeMissing} and {@code scalarCMissing}; {@code scalarCDiffering}
     * counts the pixels where the C tracer's image differs from tick1's; {@code processes} is how many
     * processes the runs started (the yardsticks' builds not counted).
     */
    record Whole(Map<String, Double> phases, Timing startup, Timing courseCode, String courseCodeMissing,
            Timing handoutStyle, Timing crowd10, Timing crowd10k, Timing endToEnd, String endToEndSize,
            Timing scalarC, String scalarCMissing, long scalarCDiffering, int processes) {
    }

    private Whole wholeRuns(ProcessRuns runs, BenchPlan plan, Path tick1File, Scene tick1) throws IOException {
        Path image = scenes.resolve("whole-run.png");
        String scene = tick1File.toString();
        Path yardsticks = Files.createDirectories(scenes.resolve("yardsticks"));
        Map<String, Double> phases = runs.phases(plan.singleRuns(), "-q", "-i", scene, "-o", image.toString());
        ProcessRuns.Beside course = runs.beside(plan.pairedRuns(), List.of("-q", "-i", scene, "-o", image.toString()),
                () -> CourseCode.build(yardsticks, tick1File, yardsticks.resolve("course-code.png")));
        Timing handoutStyle = runs.java(plan.singleRuns(), HandoutStyleRender.class.getName(), scene,
                image.toString());
        Path crowd10 = scenes.resolve("crowd-10.xml"), crowd10k = scenes.resolve("crowd-10000.xml");
        Files.writeString(crowd10, CrowdScene.xml(10));
        Files.writeString(crowd10k, CrowdScene.xml(10_000));
        Timing ten = runs.tick1(plan.singleRuns(), "-q", "-i", crowd10.toString(), "-o", image.toString());
        Timing tenThousand = runs.tick1(plan.singleRuns(), "-q", "-i", crowd10k.toString(), "-o", image.toString());
        int w = plan.bigWidth(), h = plan.bigHeight(), samples = 4;
        ScalarC[] c = new ScalarC[1];
        ProcessRuns.Beside big = runs.beside(plan.bigRuns(), List.of("-q", "-i", scene, "-o", image.toString(),
                "--width", "" + w, "--height", "" + h, "--samples", "" + samples), () -> {
                    c[0] = ScalarC.build(yardsticks, tick1, w, h, samples);
                    return c[0].command();
                });
        long differing = big.yardstick() == null ? -1 : c[0].pixelsDifferingFrom(ImageIO.read(image.toFile()));
        Timing startup = course.tick1(), courseCode = course.yardstick(), endToEnd = big.tick1(),
                scalarC = big.yardstick();
        log.printf("  whole runs: start-up %.0f ms (course code %s, handout-style java run %.0f ms); 10 spheres %.0f "
                + "ms, 10,000 spheres %.0f ms; %d x %d x %d samples %.0f ms (scalar C %s); %s%n", startup.median(),
                courseCode == null ? "not run" : String.format(Locale.ROOT, "%.0f ms", courseCode.median()),
                handoutStyle.median(), ten.median(), tenThousand.median(), w, h, samples, endToEnd.median(),
                scalarC == null ? "not run" : String.format(Locale.ROOT, "%.0f ms", scalarC.median()),
                "fresh processes: " + runs.started());
        Files.deleteIfExists(image);
        return new Whole(phases, startup, courseCode, course.missing(), handoutStyle, ten, tenThousand, endToEnd,
                w + " x " + h, scalarC, big.missing(), differing, runs.started());
    }

    private static Scene load(Path file) {
        return new SceneLoader(file, false).getScene();
    }
}
