package gfx.tick1;

import gfx.tick1.bench.Bench;
import gfx.tick1.compare.CompareCommand;
import gfx.tick1.diagnose.DiagnoseCommand;
import gfx.tick1.diff.DiffCommand;
import gfx.tick1.fast.FastRenderer;
import gfx.tick1.grade.GradeCommand;
import gfx.tick1.image.PngOutput;
import gfx.tick1.preview.Preview;
import gfx.tick1.render.SamplePattern;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.SceneException;
import gfx.tick1.scene.SceneLoader;
import gfx.tick1.starter.StarterCommand;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ForkJoinPool;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** The command line: renders a Tick 1 scene file to a PNG image. */
@Command(name = "tick1", mixinStandardHelpOptions = true, versionProvider = Version.class,
        sortOptions = false, usageHelpAutoWidth = true,
        description = "Renders a Tick 1 scene (spheres, an ambient light, one point light, Phong shading) "
                + "to a PNG image, pixel for pixel as the Cambridge Computer Graphics course expects.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:the image was written",
            "1:the scene file is missing, unreadable or invalid",
            "2:the command line is wrong",
            "3:the image could not be written (any existing file is left as it was)",
            "4:an internal error (a bug: please report it)"})
public final class Tick1 implements Callable<Integer> {

    public static final int EXIT_OK = 0;
    public static final int EXIT_BAD_SCENE = 1;
    public static final int EXIT_USAGE = 2;
    public static final int EXIT_CANNOT_WRITE = 3;
    public static final int EXIT_INTERNAL = 4;

    /** The largest width or height accepted; the frame must also fit in the JVM's heap. */
    public static final int MAX_DIMENSION = 16384;

    @Spec
    private CommandSpec spec;

    @Option(names = {"-i", "--input"}, paramLabel = "SCENE.xml", defaultValue = "basic_scene.xml",
            description = "The scene file to render (default: ${DEFAULT-VALUE}).")
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
                    + "faithful image through pixel centres; at most " + SamplePattern.MAX_SAMPLES + "). The same "
                    + "image on every run.")
    private int samples;

    @Option(names = "--threads", paramLabel = "N",
            description = "Threads to render with (default: all ${sys:tick1.cores} cores). The image is the same "
                    + "for any number.")
    private Integer threads;

    @Option(names = "--intersection", paramLabel = "METHOD", defaultValue = "robust",
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

    public Tick1() {
        this(System.out);
    }

    /** @param binaryOut where {@code --output -} sends the PNG bytes */
    public Tick1(OutputStream binaryOut) {
        this.binaryOut = binaryOut;
    }

    public static void main(String[] args) {
        Timings.mainStarted();
        CommandLine commandLine = commandLine(new Tick1(), args);
        int status;
        try {
            status = commandLine.execute(args);
        } catch (OutOfMemoryError e) {
            // Picocli handles exceptions, not errors; running out of heap is the one a user can fix.
            status = outOfMemory(commandLine.getErr());
        }
        System.exit(status);
    }

    private static int outOfMemory(PrintWriter err) {
        err.println("tick1: Java ran out of memory (it may use " + (Runtime.getRuntime().maxMemory() >> 20)
                + " MiB); give it more with JAVA_OPTS=-Xmx...");
        err.flush();
        return EXIT_INTERNAL;
    }

    /** A subcommand's name, and how to make it (only when the full command line is built). */
    private record Subcommand(String name, Supplier<Object> command) {
    }

    /** The subcommands, in the order the help lists them. */
    private static final List<Subcommand> SUBCOMMANDS = List.of(new Subcommand("compare", CompareCommand::new),
            new Subcommand("diagnose", DiagnoseCommand::new), new Subcommand("diff", DiffCommand::new),
            new Subcommand("grade", GradeCommand::new),
            new Subcommand("starter", StarterCommand::new), new Subcommand("bench", Bench::new),
            new Subcommand("preview", Preview::new));

    /**
     * The command line for these arguments. Picocli reads every registered command's annotations
     * when it is built, which was the largest part of a 640 x 480 render's start-up; a plain
     * render (options only, no subcommand named, no help asked for) cannot reach a subcommand,
     * so it is built without them. Anything else gets the full command line.
     */
    static CommandLine commandLine(Tick1 command, String... args) {
        boolean plainRender = args.length > 0 && args[0].startsWith("-");
        for (String arg : args) {
            boolean asksForHelpOrVersion = arg.equals("--help") || arg.equals("--version")
                    || arg.matches("-[^-]*[hV].*"); // -h, -V, and clusters such as -qh
            boolean namesASubcommand = SUBCOMMANDS.stream().anyMatch(subcommand -> subcommand.name().equals(arg));
            plainRender &= !namesASubcommand && !asksForHelpOrVersion;
        }
        return plainRender ? configure(new CommandLine(command)) : commandLine(command);
    }

    /** The configured command line, as {@link #main} runs it; tests run it the same way. */
    public static CommandLine commandLine(Tick1 command) {
        CommandLine commandLine = new CommandLine(command);
        SUBCOMMANDS.forEach(subcommand -> commandLine.addSubcommand(subcommand.name(), subcommand.command().get()));
        // Every subcommand's --version says which build it is, as tick1 --version does.
        commandLine.getSubcommands().values()
                .forEach(subcommand -> subcommand.getCommandSpec().versionProvider(new Version()));
        return configure(commandLine);
    }

    private static CommandLine configure(CommandLine commandLine) {
        System.setProperty("tick1.cores", Integer.toString(Runtime.getRuntime().availableProcessors()));
        commandLine.setCaseInsensitiveEnumValuesAllowed(true);
        commandLine.setParameterExceptionHandler((e, args) -> {
            PrintWriter err = e.getCommandLine().getErr();
            String name = e.getCommandLine().getCommandSpec().qualifiedName();
            err.println(name + ": " + e.getMessage() + " (see " + name + " --help)");
            err.flush();
            return EXIT_USAGE;
        });
        commandLine.setExecutionExceptionHandler((e, cl, parseResult) -> {
            PrintWriter err = cl.getErr();
            for (Throwable cause = e; cause != null; cause = cause.getCause()) {
                if (cause instanceof OutOfMemoryError) {
                    return outOfMemory(err);
                }
            }
            err.println("tick1: internal error: " + e + " (please report this with the scene file)");
            err.flush();
            return EXIT_INTERNAL;
        });
        return commandLine;
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
            err.println(e.getMessage());
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
        int cores = Runtime.getRuntime().availableProcessors();
        if (threads != null && (threads < 1 || threads > 256)) {
            return "--threads " + threads + ": must be from 1 to 256";
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
        if (threads == null) {
            threads = cores;
        }
        return null;
    }

    private BufferedImage render(Scene scene, PrintWriter err) {
        FastRenderer renderer = new FastRenderer(width, height, new SamplePattern(samples), intersection);
        Progress progress = new Progress(err, height, !quiet && System.console() != null);
        ForkJoinPool pool = new ForkJoinPool(threads);
        try {
            // A parallel stream started inside a pool's task runs on that pool's threads.
            return pool.submit(() -> renderer.render(scene, progress)).get();
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
            err.println(output + ": cannot write the image: " + describe(e));
            return EXIT_CANNOT_WRITE;
        }
        if (!quiet && !output.equals("-")) {
            spec.commandLine().getOut().println("Wrote " + output + " (" + width + " x " + height + ")");
        }
        return EXIT_OK;
    }

    private static String describe(IOException e) {
        if (e instanceof java.nio.file.AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof java.nio.file.NoSuchFileException) {
            return "no such directory";
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }
}
