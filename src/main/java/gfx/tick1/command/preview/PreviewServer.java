package gfx.tick1.command.preview;

import com.sun.net.httpserver.Headers;
import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.fast.FastRenderer;
import gfx.tick1.engine.render.SamplePattern;
import gfx.tick1.engine.scene.SceneException;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The previewer's HTTP server, on 127.0.0.1 only. It answers:
 * <ul>
 *   <li>{@code GET /}, {@code /preview.js}, {@code /preview.css}: the page;</li>
 *   <li>{@code GET /three/...}: three.js, from its WebJar;</li>
 *   <li>{@code GET /api/scene} and {@code GET /api/render}: the scene named on the command line
 *       (read afresh each time, so reloading the page shows the file as it is now), as JSON and as
 *       the ray-traced PNG ({@code {"png": base64}}, see {@link #renderWhileTheClientWaits});</li>
 *   <li>{@code POST /api/scene?name=N} and {@code POST /api/render?name=N}: the same for a scene
 *       file the page uploads (the request body), parsed in memory: nothing is written to disk.</li>
 * </ul>
 * A scene the loader rejects is answered 422 with {@code {"error": message}}, the message being
 * the CLI's own {@code file:line:column} line. The render is the CLI's: {@link FastRenderer} at the
 * CLI's default 640 x 480.
 *
 * <p>Nothing a client does can hold the server: every request must arrive, headers and body,
 * within {@link #REQUEST_DEADLINE_SECONDS} ({@link RequestDeadline}: a stalled connection is
 * closed and its thread freed), at most {@link #CONCURRENT_RENDERS} renders run at a
 * time, a scene of more than {@link #RENDER_BUDGET} sphere-pixels is refused before it is
 * rendered, a render still running after {@link #RENDER_DEADLINE_SECONDS} is stopped, and a
 * render whose client has gone is stopped within a fraction of a second. Each refusal is one
 * clear message.
 */
public final class PreviewServer implements AutoCloseable {

    /** The CLI's default image size, so that the panel shows what {@code tick1 -i SCENE} writes. */
    public static final int IMAGE_WIDTH = 640, IMAGE_HEIGHT = 480;
    /** The name an upload is given in messages when the page sends none. */
    private static final String UNNAMED = "scene.xml";

    /** How long a client has to send a whole request, headers and body. */
    public static final int REQUEST_DEADLINE_SECONDS = 10;
    /** How many renders run at the same time; more wait, up to the render deadline. */
    public static final int CONCURRENT_RENDERS = 2;
    /**
     * The most spheres x pixels a render may cost: the bundled scenes cost up to 3 x 10^7, and a
     * scene at the budget (about 30,000 spheres at 640 x 480) still renders in seconds.
     */
    public static final long RENDER_BUDGET = 10_000_000_000L;
    /** How long one render may run (or wait for its turn) before it is stopped. */
    public static final int RENDER_DEADLINE_SECONDS = 30;

    /** How often an answer still rendering sends a space, to find out whether its client is still there. */
    private static final long HEARTBEAT_MILLIS = 200;

    private static final Semaphore RENDERS = new Semaphore(CONCURRENT_RENDERS, true);
    /** Where renders run, while the request's own thread keeps its client's connection under watch. */
    private static final ExecutorService RENDER_THREADS = Executors.newCachedThreadPool(task -> {
        Thread thread = new Thread(task, "tick1-preview-render");
        thread.setDaemon(true);
        return thread;
    });
    /** Renders stopped because their client had gone, for the tests. */
    private static final AtomicInteger RENDERS_ABANDONED = new AtomicInteger();

    private final HttpServer server;
    private final RequestDeadline executor;
    private final Path commandLineScene;
    private final LoopbackGuard guard;
    private final StaticFiles files = new StaticFiles();
    private final String contentSecurityPolicy;

    private PreviewServer(HttpServer server, RequestDeadline executor, Path commandLineScene) {
        this.server = server;
        this.executor = executor;
        this.commandLineScene = commandLineScene;
        this.guard = new LoopbackGuard(server.getAddress().getPort());
        // The page loads only its own files; its one inline script is the import map, allowed by hash.
        this.contentSecurityPolicy = "default-src 'self'; script-src 'self' " + files.importMapHash()
                + "; img-src 'self' blob: data:; object-src 'none'; base-uri 'none'; form-action 'none';"
                + " frame-ancestors 'none'";
    }

    /**
     * Starts a server on 127.0.0.1:{@code port} (0: any free port).
     *
     * @param commandLineScene the scene shown when the page opens, or null for none
     * @throws IOException when the port cannot be bound (a {@link java.net.BindException} when taken)
     */
    public static PreviewServer start(Path commandLineScene, int port) throws IOException {
        HttpServer server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 0);
        // A few threads, so that a long render does not hold up the page's other requests.
        RequestDeadline executor = new RequestDeadline(4, TimeUnit.SECONDS.toMillis(REQUEST_DEADLINE_SECONDS));
        PreviewServer preview = new PreviewServer(server, executor, commandLineScene);
        server.createContext("/", preview::handle);
        server.setExecutor(executor);
        server.start();
        return preview;
    }

    /** The page's address, e.g. {@code http://127.0.0.1:43125/}. */
    public URI uri() {
        return URI.create("http://127.0.0.1:" + server.getAddress().getPort() + "/");
    }

    @Override
    public void close() {
        server.stop(0);
        executor.shutdownNow();
    }

    private void handle(HttpExchange exchange) throws IOException {
        try {
            route(exchange);
        } catch (RuntimeException e) {
            if (exchange.getResponseCode() != -1) {
                throw e;   // the answer had begun: nothing better to do than drop the connection
            }
            // Reaches here only through a bug: say so on the page rather than drop the connection.
            sendJson(exchange, 500, SceneJson.error("tick1 preview: internal error: " + e
                    + " (please report this with the scene file)"));
        } finally {
            exchange.close();
        }
    }

    private void route(HttpExchange exchange) throws IOException {
        Headers headers = exchange.getResponseHeaders();
        headers.set("X-Content-Type-Options", "nosniff");
        headers.set("Referrer-Policy", "no-referrer");
        Optional<String> refusal = guard.refusal(exchange.getRequestHeaders());
        if (refusal.isPresent()) {
            sendText(exchange, 403, "Forbidden: " + refusal.get());
            return;
        }
        String method = exchange.getRequestMethod();
        String path = exchange.getRequestURI().getPath();
        boolean api = path.equals("/api/scene") || path.equals("/api/render");
        if (!(api && method.equals("POST"))) {
            RequestDeadline.requestRead();   // no body to wait for
        }
        if (api && method.equals("GET")) {
            answer(exchange, path, commandLineScene == null ? null : commandLineScene.toString(),
                    () -> new SceneLoader(commandLineScene, false));
        } else if (api && method.equals("POST")) {
            String name = uploadName(exchange.getRequestURI().getRawQuery());
            byte[] upload = readUpload(exchange, name);
            RequestDeadline.requestRead();
            if (upload != null) {
                answer(exchange, path, name, () -> new SceneLoader(name, upload, false));
            }
        } else if (method.equals("GET")) {
            Optional<StaticFiles.File> found = files.find(path);
            if (found.isEmpty()) {
                sendText(exchange, 404, "Not found");
                return;
            }
            StaticFiles.File file = found.get();
            if (file.contentType().startsWith("text/html")) {
                headers.set("Content-Security-Policy", contentSecurityPolicy);
            }
            send(exchange, 200, file.contentType(), file.bytes());
        } else {
            headers.set("Allow", api ? "GET, POST" : "GET");
            sendText(exchange, 405, "Method not allowed");
        }
    }

    /** A source of a loaded scene: the loader, which throws {@link SceneException} for a bad file. */
    private interface SceneSource {
        SceneLoader load();
    }

    /** Answers {@code /api/scene} with the scene as JSON, or {@code /api/render} with its PNG. */
    private static void answer(HttpExchange exchange, String path, String name, SceneSource source)
            throws IOException {
        exchange.getResponseHeaders().set("Cache-Control", "no-store");
        if (name == null) {
            sendJson(exchange, 404, SceneJson.error("no scene was named on the command line"));
            return;
        }
        SceneLoader loader;
        try {
            loader = source.load();
        } catch (SceneException e) {
            sendJson(exchange, 422, SceneJson.error(e.getMessage()));
            return;
        }
        if (path.equals("/api/scene")) {
            sendJson(exchange, 200, SceneJson.describe(name, loader.getScene(), loader.getWarnings()));
        } else {
            long cost = (long) loader.getScene().getObjects().size() * IMAGE_WIDTH * IMAGE_HEIGHT;
            if (cost > RENDER_BUDGET) {
                sendJson(exchange, 422, SceneJson.error(name + ": " + loader.getScene().getObjects().size()
                        + " spheres at " + IMAGE_WIDTH + " x " + IMAGE_HEIGHT + " is more than the previewer renders "
                        + "(at most " + RENDER_BUDGET / (IMAGE_WIDTH * IMAGE_HEIGHT) + " spheres); render it with "
                        + "tick1 --input instead"));
                return;
            }
            exchange.getResponseHeaders().set("Content-Type", "application/json; charset=utf-8");
            exchange.sendResponseHeaders(200, 0);
            try (OutputStream out = exchange.getResponseBody()) {
                out.write(renderWhileTheClientWaits(loader, name, out).getBytes(StandardCharsets.UTF_8));
            }
        }
    }

    /**
     * The render's answer, {@code {"png": base64}} or {@code {"error": message}}, rendered on a
     * thread of its own while this one watches the client.
     *
     * <p>The JDK's HTTP server never says that a client has closed its connection; writing to it
     * is the only way to find out. So the answer is begun at once, and while the render runs a
     * space is sent every {@link #HEARTBEAT_MILLIS} (white space before a JSON value is still JSON,
     * which is why the image is sent as JSON and not as a bare PNG). Once the client has gone, a
     * write fails within a heartbeat or two (the first is refused by the client's end, the next
     * one fails here), and the render is stopped at its next row.
     *
     * @throws IOException when the client has gone
     */
    private static String renderWhileTheClientWaits(SceneLoader loader, String name, OutputStream out)
            throws IOException {
        AtomicBoolean clientGone = new AtomicBoolean();
        Future<BufferedImage> render = RENDER_THREADS.submit(() -> renderWithinDeadline(loader, clientGone));
        BufferedImage image;
        while (true) {
            try {
                image = render.get(HEARTBEAT_MILLIS, TimeUnit.MILLISECONDS);
                break;
            } catch (TimeoutException stillRendering) {
                try {
                    out.write(' ');
                    out.flush();
                } catch (IOException gone) {
                    abandon(render, clientGone);
                    RENDERS_ABANDONED.incrementAndGet();
                    throw gone;
                }
            } catch (InterruptedException e) {
                abandon(render, clientGone);
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while rendering", e);
            } catch (ExecutionException e) {
                // The answer has begun (200 and spaces): say what went wrong in its body.
                return SceneJson.error("tick1 preview: internal error: " + e.getCause()
                        + " (please report this with the scene file)");
            }
        }
        if (image == null) {
            return SceneJson.error(name + ": not rendered within " + RENDER_DEADLINE_SECONDS + " s (the previewer "
                    + "renders " + CONCURRENT_RENDERS + " scenes at a time); render it with tick1 --input instead");
        }
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        PngOutput.write(image, png);
        return SceneJson.image(png.toByteArray());
    }

    /**
     * Stops a render nobody waits for: a running one at its next row, through {@code clientGone};
     * one still waiting for its turn at once, through the interrupt, so that it holds no thread.
     */
    private static void abandon(Future<BufferedImage> render, AtomicBoolean clientGone) {
        clientGone.set(true);
        render.cancel(true);
    }

    /** How many renders have been stopped because their client had gone. */
    static int rendersAbandoned() {
        return RENDERS_ABANDONED.get();
    }

    /**
     * The scene's render, waiting for a turn among {@link #CONCURRENT_RENDERS}, or null when the
     * wait and the render together take longer than {@link #RENDER_DEADLINE_SECONDS} or the
     * client has gone.
     */
    private static BufferedImage renderWithinDeadline(SceneLoader loader, AtomicBoolean clientGone) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(RENDER_DEADLINE_SECONDS);
        try {
            if (!RENDERS.tryAcquire(RENDER_DEADLINE_SECONDS, TimeUnit.SECONDS)) {
                return null;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
        try {
            if (clientGone.get()) {
                return null;
            }
            return new FastRenderer(IMAGE_WIDTH, IMAGE_HEIGHT, new SamplePattern(1)).render(loader.getScene(), rows -> {
                if (clientGone.get() || System.nanoTime() > deadline) {
                    throw new CancellationException();
                }
            });
        } catch (CancellationException e) {
            return null;
        } finally {
            RENDERS.release();
        }
    }

    /**
     * The request body, at most the loader's {@link SceneLoader#MAX_FILE_BYTES}. A larger one is
     * answered 413 with the message the loader gives for a file that large, and null returned.
     */
    private static byte[] readUpload(HttpExchange exchange, String name) throws IOException {
        String declared = exchange.getRequestHeaders().getFirst("Content-Length");
        long length = declared == null ? 0 : parseLength(declared);
        if (length > SceneLoader.MAX_FILE_BYTES) {
            sendJson(exchange, 413, SceneJson.error(name + ": file is " + length + " bytes, expected at most "
                    + SceneLoader.MAX_FILE_BYTES + " (64 MiB)"));
            return null;
        }
        byte[] bytes;
        try (InputStream in = exchange.getRequestBody()) {
            // One byte past the limit tells a body that is too long from one just long enough.
            bytes = in.readNBytes((int) SceneLoader.MAX_FILE_BYTES + 1);
        }
        if (bytes.length > SceneLoader.MAX_FILE_BYTES) {
            sendJson(exchange, 413, SceneJson.error(name + ": file is larger than " + SceneLoader.MAX_FILE_BYTES
                    + " bytes (64 MiB)"));
            return null;
        }
        return bytes;
    }

    private static long parseLength(String declared) {
        try {
            return Long.parseLong(declared.strip());
        } catch (NumberFormatException e) {
            return Long.MAX_VALUE;
        }
    }

    /**
     * The uploaded file's name from {@code ?name=}, used only in messages: control characters
     * replaced and the length bounded, as the loader does with values it quotes.
     */
    private static String uploadName(String rawQuery) {
        if (rawQuery != null) {
            for (String parameter : rawQuery.split("&")) {
                if (parameter.startsWith("name=")) {
                    String name = URLDecoder.decode(parameter.substring(5), StandardCharsets.UTF_8)
                            .replaceAll("\\p{Cntrl}", "?");
                    if (!name.isBlank()) {
                        return name.length() <= 200 ? name : name.substring(0, 197) + "...";
                    }
                }
            }
        }
        return UNNAMED;
    }

    private static void sendText(HttpExchange exchange, int status, String text) throws IOException {
        send(exchange, status, "text/plain; charset=utf-8", text.getBytes(StandardCharsets.UTF_8));
    }

    private static void sendJson(HttpExchange exchange, int status, String json) throws IOException {
        send(exchange, status, "application/json; charset=utf-8", json.getBytes(StandardCharsets.UTF_8));
    }

    private static void send(HttpExchange exchange, int status, String contentType, byte[] body) throws IOException {
        exchange.getResponseHeaders().set("Content-Type", contentType);
        exchange.sendResponseHeaders(status, body.length == 0 ? -1 : body.length);
        try (OutputStream out = exchange.getResponseBody()) {
            out.write(body);
        }
    }
}
