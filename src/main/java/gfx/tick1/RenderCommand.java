package gfx.tick1;

import gfx.tick1.cli.ExitStatus;
import gfx.tick1.cli.ExitStatuses;
import gfx.tick1.fast.FastRenderer;
import gfx.tick1.image.PngOutput;
import gfx.tick1.io.IoErrors;
import gfx.tick1.io.ProgressLine;
import gfx.tick1.render.SamplePattern;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.SceneException;
import gfx.tick1.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ForkJoinPool;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ScopeType;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

/**
 * {@code tick1}: renders a Tick 1 scene file to a PNG image. As the top command it also carries
 * what every subcommand inherits ({@code scope = INHERIT}): --help and --version, the version
 * provider, options in the order written, the help's width and its "Exit status:" heading.
 */
@Command(name = "tick1", scope = ScopeType.INHERIT, mixinStandardHelpOptions = true, versionProvider = Version.class,
        sortOptions = false, usageHelpAutoWidth = true, exitCodeListHeading = "%nExit status:%n",
        description = "Renders a Tick 1 scene (spheres, an ambient light, one point light, Phong shading) "
                + "to a PNG image, pixel for pixel as the Cambridge Computer Graphics course expects.")
public final class RenderCommand implements Callable<Integer> {

    @ExitStatus("the image was written")
    public static final int EXIT_OK = 0;
    @ExitStatus("the scene file is missing, unreadable or invalid")
    public static final int EXIT_BAD_SCENE = 1;
    public static final int EXIT_USAGE = ExitStatuses.EXIT_USAGE;
    @ExitStatus("the image could not be written (any existing file is left as it was)")
    public static final int EXIT_CANNOT_WRITE = 3;

    /** The largest width or height accepted; the frame must also fit in the JVM's heap. */
    public static final int MAX_DIMENSION = 16384;

    /** The largest --threads accepted. */
    private static final int MAX_THREADS = 256;

    @Spec
    private CommandSpec spec;

    @Option(names = {"-i", "--input"}, paramLabel = "SCENE.xml", defaultValue = "basic_scene.xml",
            description = "The scene file to render (default: ${DEFAULT-VALUE} in the current folder; "
                    + "tick1 starter writes one).")
    private String input;

    @Option(names = {"-o", "--output"}, paramLabel = "IMAGE.png", defaultValue = "output.png",
            description = "The PNG file to write, or - for standard output (default: ${DEFAULT-VALUE}). "
                    + "It is replaced only by a complete image.")
    private String output;

    @Option(names = "--width", paramLabel = "PIXELS", defaultValue = "640",
            description = "Image width (default: ${DEFAULT-VALUE}, at most " + MAX_DIMENSION + ").")
    private int width;

    @Option(names = "--height", paramLabel = "PIXELS", defaultValue = "480",
            description = "Image height (default: ${DEFAULT-VALUE}, at most " + MAX_DIMENSION + ").")
    private int height;

    @Option(names = "--samples", paramLabel = "N", defaultValue = "1",
            description = "Rays per pixel, averaged before the conversion to bytes (default: ${DEFAULT-VALUE}, the "
                    + "course's image: one ray a pixel, aimed as the starter code's camera aims it, through the "
                    + "centre of the pixel's column and one pixel above the centre of its row; at most "
                    + SamplePattern.MAX_SAMPLES
                    + "). More samples spread the rays over the pixel; the same image on every run.")
    private int samples;

    @Option(names = "--threads", paramLabel = "N",
            description = "Threads to render with (default: one per core; this machine has "
                    + "${sys:tick1.cores}). The image is the same "
                    + "for any number.")
    private Integer threads;

    @Option(names = "--intersection", paramLabel = "METHOD", defaultValue = "robust",
            converter = IntersectionName.class,
            description = "How rays meet spheres: robust (default: the handout's formula wherever it is accurate, "
                    + "a numerically stable one where it is not, e.g. giant or far-away spheres), handout (the "
                    + "handout's formula as it stands) or stable (the stable formula everywhere; not bit-identical "
                    + "to the course's images). See docs/hard-cases.md.")
    private Intersection intersection;

    @Option(names = "--strict", description = "Treat warnings about the scene file as errors.")
    private boolean strict;

    @Option(names = {"-q", "--quiet"}, description = "Print nothing but errors.")
    private boolean quiet;

    @Option(names = "--timings", hidden = true, description = "Print where the run's time went.")
    private boolean showTimings;

    private final Timings timings = new Timings();

    private final OutputStream binaryOut;

    public RenderCommand() {
        this(System.out);
    }

    /** @param binaryOut where {@code --output -} sends the PNG bytes */
    public RenderCommand(OutputStream binaryOut) {
        this.binaryOut = binaryOut;
    }

    /** {@code --intersection}: a method by its lower-case name, as the help writes it, in any case. */
    static final class IntersectionName implements ITypeConverter<Intersection> {
        @Override
        public Intersection convert(String name) {
            for (Intersection method : Intersection.values()) {
                if (method.name().equalsIgnoreCase(name)) {
                    return method;
                }
            }
            List<String> names = Arrays.stream(Intersection.values())
                    .map(method -> method.name().toLowerCase(Locale.ROOT)).toList();
            throw new TypeConversionException("expected one of " + String.join(", ", names)
                    + " but was '" + name + "'");
        }
    }

    /** Whether the input was left to its default: a missing default scene then gets a hint. */
    private boolean inputIsTheDefault() {
        return !spec.commandLine().getParseResult().hasMatchedOption("--input");
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        timings.end("command line");
        String usage = checkOptions();
        if (usage != null) {
            throw new ParameterException(spec.commandLine(), usage);
        }

        Scene scene;
        try {
            SceneLoader loader = new SceneLoader(Path.of(input), strict);
            scene = loader.getScene();
            if (!quiet) {
                loader.getWarnings().forEach(err::println);
            }
        } catch (InvalidPathException e) {
            err.println(input + ": not a valid file name");
            return EXIT_BAD_SCENE;
        } catch (SceneException e) {
            boolean defaultSceneMissing = inputIsTheDefault() && !Files.exists(Path.of(input));
            String hint = defaultSceneMissing ? " (give a scene with -i SCENE.xml; see tick1 --help)" : "";
            err.println(e.getMessage() + hint);
            return EXIT_BAD_SCENE;
        }

        timings.end("scene");
        BufferedImage image = render(scene, err);
        timings.end("render");
        int status = write(image, err);
        timings.end("png");
        if (showTimings) {
            timings.print(err);
        }
        return status;
    }

    /** Checks what picocli's types cannot: ranges, and that the frame fits in memory. */
    private String checkOptions() {
        if (width < 1 || width > MAX_DIMENSION) {
            return "--width " + width + ": must be from 1 to " + MAX_DIMENSION;
        }
        if (height < 1 || height > MAX_DIMENSION) {
            return "--height " + height + ": must be from 1 to " + MAX_DIMENSION;
        }
        if (samples < 1 || samples > SamplePattern.MAX_SAMPLES) {
            return "--samples " + samples + ": must be from 1 to " + SamplePattern.MAX_SAMPLES;
        }
        if (threads != null && (threads < 1 || threads > MAX_THREADS)) {
            return "--threads " + threads + ": must be from 1 to " + MAX_THREADS;
        }
        // The renderer holds the frame twice (its pixel array and the image), 4 bytes a pixel each,
        // and the PNG encoder needs room of its own: half the heap is a safe ceiling.
        long needed = 8L * width * height;
        long available = Runtime.getRuntime().maxMemory() / 2;
        if (needed > available) {
            return String.format("a %d x %d image needs about %d MiB, more than half of the %d MiB this Java "
                    + "may use; raise that with JAVA_OPTS=-Xmx...", width, height, needed >> 20,
                    Runtime.getRuntime().maxMemory() >> 20);
        }
        return null;
    }

    /** The threads to render with: --threads, or one a core. */
    private int threadCount() {
        return threads != null ? threads : Runtime.getRuntime().availableProcessors();
    }

    private BufferedImage render(Scene scene, PrintWriter err) {
        FastRenderer renderer = new FastRenderer(width, height, new SamplePattern(samples), intersection);
        // The starter code printed a line per row; this shows one line, once a render takes long enough to wonder.
        ProgressLine progress = new ProgressLine(err, !quiet && System.console() != null, Duration.ofMillis(500),
                Duration.ofMillis(100));
        ForkJoinPool pool = new ForkJoinPool(threadCount());
        try {
            // A parallel stream started inside a pool's task runs on that pool's threads.
            return pool.submit(() -> renderer.render(scene,
                    rowsDone -> progress.show(String.format("rendering: %3d%%", 100L * rowsDone / height)))).get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while rendering", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        } finally {
            pool.shutdownNow();
            progress.finish();
        }
    }

    private int write(BufferedImage image, PrintWriter err) {
        try {
            if (output.equals("-")) {
                PngOutput.write(image, binaryOut);
                // System.out is a PrintStream, which records a failed write (a closed pipe, a
                // full disk) instead of throwing.
                if (binaryOut instanceof java.io.PrintStream printStream && printStream.checkError()) {
                    throw new IOException("standard output was closed or could not be written");
                }
            } else {
                PngOutput.write(image, Path.of(output));
            }
        } catch (InvalidPathException e) {
            err.println(output + ": cannot write the image: not a valid file name");
            return EXIT_CANNOT_WRITE;
        } catch (IOException e) {
            err.println(output + ": cannot write the image: " + IoErrors.reason(e));
            return EXIT_CANNOT_WRITE;
        }
        // Only a file is worth naming; and behind -o /dev/stdout the line would land in the PNG.
        if (!quiet && !output.equals("-") && Files.isRegularFile(Path.of(output))) {
            spec.commandLine().getOut().println("Wrote " + output + " (" + width + " x " + height + ")");
        }
        return EXIT_OK;
    }
}
