package gfx.tick1.command.preview;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.command.shared.cli.ExitStatuses;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.scene.SceneException;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.Desktop;
import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.io.PrintWriter;
import java.net.BindException;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code tick1 preview}: a web page on this machine that shows a scene in 3D beside its ray-traced image. */
@Command(name = "preview",
        description = {
            "Shows a scene in 3D in the browser, beside its ray-traced image.",
            "Serves a page, to this machine only, that shows a scene in 3D (ground grid, axes, the camera, "
                    + "the light, the spheres) with what the camera sees and the ray-traced image beside it. "
                    + "Drop scene files onto the page, or pick one, to see them; reload the page to re-read SCENE.xml.",
            "Runs until interrupted (Ctrl-C)."})
public final class PreviewCommand implements Callable<Integer> {

    /** When the thread serving is interrupted inside Java, as a program embedding the previewer does. */
    public static final int EXIT_STOPPED = 0;
    @ExitStatus("SCENE.xml does not exist")
    public static final int EXIT_NO_SCENE = 1;
    @ExitStatus("the command line is wrong, or the port cannot be used")
    public static final int EXIT_USAGE = ExitStatuses.EXIT_USAGE;

    /**
     * Java ends on Ctrl-C with 128 plus the signal's number (SIGINT, 2), the status by which shells
     * and make know that a program was interrupted. The previewer keeps that convention rather than
     * catching the signal, which Java offers only through an unsupported API.
     */
    @ExitStatus("stopped with Ctrl-C (the usual status of an interrupted program)")
    public static final int EXIT_INTERRUPTED = 130;

    @Spec
    private CommandSpec spec;

    @Parameters(arity = "0..1", paramLabel = "SCENE.xml",
            description = "The scene shown when the page opens (default: none; drop one onto the page).")
    private String scene;

    @Option(names = "--port", paramLabel = "N", defaultValue = "0",
            description = "The port to serve on, on 127.0.0.1 (default: ${DEFAULT-VALUE}, any free port).")
    private int port;

    @Option(names = "--no-open", description = "Do not open a browser; just print the page's address.")
    private boolean noOpen;

    /** Counted down only by interruption: the previewer runs until the JVM is stopped. */
    private final CountDownLatch stopped = new CountDownLatch(1);

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (port < 0 || port > 65535) {
            throw new ParameterException(spec.commandLine(), "--port " + port + ": must be from 0 to 65535");
        }
        Path scenePath = null;
        if (scene != null) {
            try {
                scenePath = Path.of(scene);
            } catch (InvalidPathException e) {
                err.println("tick1 preview: " + scene + ": not a valid file name");
                return EXIT_NO_SCENE;
            }
            // Only a missing file stops the previewer: anything wrong inside it is shown on the page,
            // where a corrected file can be dropped.
            if (!Files.exists(scenePath)) {
                err.println("tick1 preview: " + scene + ": no such file");
                return EXIT_NO_SCENE;
            }
            try {
                new SceneLoader(scenePath, false);
            } catch (SceneException e) {
                // The page shows it too, but a terminal is where a user looks first.
                err.println("tick1 preview: " + e.getMessage() + " (also on the page, where a corrected file can be "
                        + "dropped)");
                err.flush();
            }
        }

        try (PreviewServer server = PreviewServer.start(scenePath, port)) {
            URI uri = server.uri();
            out.println("tick1 preview: " + (scene == null ? "" : scene + " at ") + uri + " (Ctrl-C to stop)");
            out.flush();
            if (!noOpen) {
                openBrowser(uri, err);
            }
            stopped.await();
        } catch (BindException e) {
            throw new CommandFailure(EXIT_USAGE, "cannot use port " + port + ": " + e.getMessage()
                    + " (choose another with --port, or --port 0 for any free one)");
        } catch (IOException e) {
            throw new CommandFailure(EXIT_USAGE, "cannot start the server: " + IoErrors.describe(e));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return EXIT_STOPPED;
    }

    /** Opens the page in the desktop's browser where there is one; otherwise the printed address has to do. */
    private static void openBrowser(URI uri, PrintWriter err) {
        try {
            if (!GraphicsEnvironment.isHeadless() && Desktop.isDesktopSupported()
                    && Desktop.getDesktop().isSupported(Desktop.Action.BROWSE)) {
                Desktop.getDesktop().browse(uri);
            }
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            err.println("tick1 preview: could not open a browser (" + e.getMessage() + "): open the address above");
        }
    }
}
