package gfx.tick1.command.render;

import gfx.tick1.command.shared.cli.Version;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.command.shared.cli.ExitStatuses;
import gfx.tick1.command.shared.cli.Invocation;
import gfx.tick1.engine.image.ImageFormat;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.io.ProgressLine;
import gfx.tick1.engine.render.SamplePattern;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.SceneException;
import gfx.tick1.engine.scene.SceneLoader;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
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
        description = {"Renders a Tick 1 scene to a PNG image, pixel for pixel as the Cambridge Computer Graphics "
                + "course expects.",
            "A scene is spheres, an ambient light and one point light, with Phong shading."})
public final class RenderCommand implements Callable<Integer> {

    @ExitStatus("the image was written")
    public static final int EXIT_OK = 0;
    @ExitStatus("the scene file is missing, unreadable or invalid")
    public static final int EXIT_BAD_SCENE = 1;
    @ExitStatus("the command line is wrong, or output.png exists and no -o was given")
    public static final int EXIT_USAGE = ExitStatuses.EXIT_USAGE;
    @ExitStatus("the image could not be written (any existing file is left as it was)")
    public static final int EXIT_CANNOT_WRITE = 3;

    /** The largest width or height accepted; the frame must also fit in the JVM's heap. */
    public static final int MAX_DIMENSION = RenderOptions.MAX_DIMENSION;

    @Spec
    private CommandSpec spec;

    @Option(names = {"-i", "--input"}, paramLabel = "SCENE.xml", defaultValue = "basic_scene.xml",
            description = "The scene file to render (default: ${DEFAULT-VALUE} in the current folder; "
                    + "tick1 starter writes one).")
    private String input;

    @Option(names = {"-o", "--output"}, paramLabel = "IMAGE.png", defaultValue = "output.png",
            description = "The PNG file to write, or - for standard output (default: ${DEFAULT-VALUE}, "
                    + "never replaced unless named). It is replaced only by a complete image.")
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

    @Option(names = "--timings", description = "Print where the run's time went (start-up, scene, render, PNG) "
            + "on standard error.")
    private boolean showTimings;

    private final Timings timings = new Timings();

    private final OutputStream binaryOut;

    /** A render started on a guess at the command line, or null. */
    private final RenderJob ahead;

    public RenderCommand() {
        this(System.out);
    }

    /** @param binaryOut where {@code --output -} sends the PNG bytes */
    public RenderCommand(OutputStream binaryOut) {
        this(binaryOut, null);
    }

    /**
     * @param binaryOut where {@code --output -} sends the PNG bytes
     * @param ahead a render started before the command line was read, on a guess at it: used only
     *     if picocli reads the same options, and stopped otherwise; or null
     */
    public RenderCommand(OutputStream binaryOut, RenderJob ahead) {
        this.binaryOut = binaryOut;
        this.ahead = ahead;
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

    /**
     * Whether the image would replace a file the user did not name: the default output.png is
     * the name the handout's own program writes, so in a student's folder it is often their render.
     */
    private boolean wouldReplaceAnUnnamedFile() {
        return !spec.commandLine().getParseResult().hasMatchedOption("--output")
                && Files.exists(Path.of(output), LinkOption.NOFOLLOW_LINKS);
    }

    /** What picocli read: the options the render depends on. */
    RenderOptions options() {
        return new RenderOptions(input, strict, width, height, samples, intersection, threads);
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        timings.end("command line");
        RenderOptions options = options();
        // A render begun on a guess at the command line counts only if picocli read the same options.
        RenderJob guessed = ahead != null && ahead.options().equals(options) ? ahead : null;
        Optional<String> usage = usageProblem(options);
        if (ahead != null && (guessed == null || usage.isPresent() || wouldReplaceAnUnnamedFile())) {
            ahead.cancel();
        }
        if (usage.isPresent()) {
            throw new ParameterException(spec.commandLine(), usage.get());
        }
        if (wouldReplaceAnUnnamedFile()) {
            err.println("tick1: " + output + " already exists (it may be your own render) and -o was not given; "
                    + "-o " + output + " replaces it, -o OTHER.png writes another");
            return EXIT_USAGE;
        }
        RenderJob job = guessed != null ? guessed : RenderJob.start(options);
        if (!sceneLoaded(job, err)) {
            return EXIT_BAD_SCENE;
        }

        timings.end("scene");
        // The starter code printed a line per row; this shows one line, once a render takes long enough to wonder.
        ProgressLine progress = new ProgressLine(err, !quiet && System.console() != null, Duration.ofMillis(500),
                Duration.ofMillis(100));
        try {
            job.awaitRender(rowsDone -> progress.show(String.format("rendering: %3d%%", 100L * rowsDone / height)));
        } finally {
            progress.finish();
        }
        timings.end("render");
        int status = write(job, err);
        timings.end("png");
        if (showTimings) {
            timings.print(err, (job == ahead ? "rendered while the command line was read: " : "") + job.stages());
        }
        return status;
    }

    /** What is wrong with the command line beyond what picocli's types check, if anything. */
    private Optional<String> usageProblem(RenderOptions options) {
        return options.problem().or(() -> ImageFormat.ofName(output).filter(format -> format != ImageFormat.PNG)
                .map(format -> "--output " + output + ": tick1 writes PNG images only (every pixel exact); name it "
                        + ImageFormat.asPng(output)));
    }

    /** Waits for the scene, prints its warnings, and says why it cannot be rendered if it cannot. */
    private boolean sceneLoaded(RenderJob job, PrintWriter err) {
        try {
            SceneLoader loader = job.scene();
            if (!quiet) {
                loader.getWarnings().forEach(err::println);
            }
            return true;
        } catch (InvalidPathException e) {
            err.println("tick1: " + input + ": not a valid file name");
        } catch (SceneException e) {
            boolean defaultSceneMissing = inputIsTheDefault() && !Files.exists(Path.of(input));
            // Most often a first run in an empty folder: the kit comes first, and it has the scene.
            String tick1 = Invocation.command();
            String hint = defaultSceneMissing ? " (to begin, " + tick1 + " starter writes the starter kit and its "
                    + "basic_scene.xml into tick1/; or give a scene with -i SCENE.xml; see " + tick1 + " --help)" : "";
            err.println("tick1: " + e.getMessage() + hint);
        }
        return false;
    }

    private int write(RenderJob job, PrintWriter err) {
        try {
            byte[] png = job.png();
            if (output.equals("-")) {
                binaryOut.write(png);
                binaryOut.flush();
                // System.out is a PrintStream, which records a failed write (a closed pipe, a
                // full disk) instead of throwing.
                if (binaryOut instanceof java.io.PrintStream printStream && printStream.checkError()) {
                    throw new IOException("standard output was closed or could not be written");
                }
            } else {
                PngOutput.write(png, Path.of(output));
            }
        } catch (InvalidPathException e) {
            err.println("tick1: " + output + ": cannot write the image: not a valid file name");
            return EXIT_CANNOT_WRITE;
        } catch (IOException e) {
            err.println("tick1: " + output + ": cannot write the image: " + IoErrors.reason(e));
            return EXIT_CANNOT_WRITE;
        }
        // Only a file is worth naming; and behind -o /dev/stdout the line would land in the PNG.
        if (!quiet && !output.equals("-") && Files.isRegularFile(Path.of(output))) {
            spec.commandLine().getOut().println("Wrote " + output + " (" + width + " x " + height + ")");
        }
        return EXIT_OK;
    }
}
