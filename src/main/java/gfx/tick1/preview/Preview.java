package gfx.tick1.preview;

import gfx.tick1.Tick1;
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
@Command(name = "preview", mixinStandardHelpOptions = true,
        sortOptions = false, usageHelpAutoWidth = true,
        header = "Shows a scene in 3D in the browser, beside its ray-traced image.",
        description = {
            "Serves a page, to this machine only, that shows a scene in 3D (ground grid, axes, the camera, "
                    + "the light, the spheres) with what the camera sees and the ray-traced image beside it. "
                    + "Drop scene files onto the page, or pick one, to see them; reload the page to re-read SCENE.xml.",
            "Runs until interrupted (Ctrl-C)."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:stopped with Ctrl-C",
            "1:SCENE.xml does not exist",
            "2:the command line is wrong, or the port cannot be used"})
public final class Preview implements Callable<Integer> {

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
                err.println(scene + ": not a valid file name");
                return Tick1.EXIT_BAD_SCENE;
            }
            // Only a missing file stops the previewer: anything wrong inside it is shown on the page,
            // where a corrected file can be dropped.
            if (!Files.exists(scenePath)) {
                err.println(scene + ": no such file");
                return Tick1.EXIT_BAD_SCENE;
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
            err.println("tick1 preview: cannot use port " + port + ": " + e.getMessage()
                    + " (choose another with --port, or --port 0 for any free one)");
            return Tick1.EXIT_USAGE;
        } catch (IOException e) {
            err.println("tick1 preview: cannot start the server: " + e.getMessage());
            return Tick1.EXIT_USAGE;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return Tick1.EXIT_OK;
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
