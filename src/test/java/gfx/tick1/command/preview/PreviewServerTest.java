package gfx.tick1.command.preview;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.SceneException;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.ResourceLock;

/** The previewer's HTTP answers, and whom it refuses: plain HTTP, no browser needed. */
@ResourceLock(PreviewServerTest.RENDERS_ABANDONED)
@Order(20)   // one of the longest classes: it starts early (junit-platform.properties)
class PreviewServerTest {

    /**
     * The program's count of renders abandoned by their client, as a resource: one test counts its own abandoned
     * render by it, so no class whose renders could be abandoned (the page's, in a browser) runs beside this one.
     */
    static final String RENDERS_ABANDONED = "gfx.tick1.command.preview.PreviewServer.rendersAbandoned";


    private static final Path TICK1_XML = Path.of("scenes", "tick1.xml");

    private final HttpClient http = HttpClient.newHttpClient();
    private PreviewServer server;

    @TempDir
    Path dir;

    @BeforeEach
    void start() throws IOException {
        server = PreviewServer.start(TICK1_XML, 0);
    }

    @AfterEach
    void stop() {
        server.close();
    }

    private int port() {
        return server.uri().getPort();
    }

    private HttpResponse<byte[]> send(HttpRequest.Builder request) throws IOException, InterruptedException {
        return http.send(request.build(), HttpResponse.BodyHandlers.ofByteArray());
    }

    private HttpRequest.Builder get(String path) {
        return HttpRequest.newBuilder(server.uri().resolve(path));
    }

    private HttpRequest.Builder upload(String path, String name, byte[] scene) {
        return HttpRequest.newBuilder(server.uri().resolve(path + "?name=" + name))
                .header("Origin", "http://127.0.0.1:" + port())
                .POST(HttpRequest.BodyPublishers.ofByteArray(scene));
    }

    /** The status line of a request written by hand, for headers HttpClient will not send (Host). */
    private String rawStatusLine(String request) throws IOException {
        try (Socket socket = new Socket("127.0.0.1", port())) {
            OutputStream out = socket.getOutputStream();
            out.write(request.getBytes(StandardCharsets.ISO_8859_1));
            out.flush();
            InputStream in = socket.getInputStream();
            StringBuilder line = new StringBuilder();
            for (int c = in.read(); c != -1 && c != '\r'; c = in.read()) {
                line.append((char) c);
            }
            return line.toString();
        }
    }

    private static String text(HttpResponse<byte[]> response) {
        return new String(response.body(), StandardCharsets.UTF_8);
    }

    @Test
    void listensOnTheLoopbackAddressOnly() {
        assertThat(server.uri().getHost()).isEqualTo("127.0.0.1");
    }

    @Test
    void servesThePageWithThreeJsFromTheClasspath() throws Exception {
        HttpResponse<byte[]> page = send(get("/"));
        assertThat(page.statusCode()).isEqualTo(200);
        assertThat(text(page)).contains("\"three\": \"/three/build/three.module.min.js\"").doesNotContain("https:");

        HttpResponse<byte[]> three = send(get("/three/build/three.module.min.js"));
        assertThat(three.statusCode()).isEqualTo(200);
        assertThat(three.headers().firstValue("Content-Type"))
                .hasValueSatisfying(type -> assertThat(type).startsWith("text/javascript"));
        assertThat(send(get("/three/examples/jsm/controls/OrbitControls.js")).statusCode()).isEqualTo(200);
    }

    @Test
    void servesNothingOutsideThePageAndThreeJs() throws IOException {
        assertThat(rawStatusLine("GET /three/../../../gfx/tick1/Tick1.class HTTP/1.1\r\nHost: 127.0.0.1:" + port()
                + "\r\nConnection: close\r\n\r\n")).isEqualTo("HTTP/1.1 404 Not Found");
        assertThat(rawStatusLine("GET /scenes/tick1.xml HTTP/1.1\r\nHost: 127.0.0.1:" + port()
                + "\r\nConnection: close\r\n\r\n")).isEqualTo("HTTP/1.1 404 Not Found");
    }

    @Test
    void answersARequestNamingItsOwnHost() throws IOException {
        assertThat(rawStatusLine("GET / HTTP/1.1\r\nHost: 127.0.0.1:" + port() + "\r\nConnection: close\r\n\r\n"))
                .isEqualTo("HTTP/1.1 200 OK");
        assertThat(rawStatusLine("GET / HTTP/1.1\r\nHost: localhost:" + port() + "\r\nConnection: close\r\n\r\n"))
                .isEqualTo("HTTP/1.1 200 OK");
    }

    @Test
    void refusesARequestNamingAnotherHost() throws IOException {
        // What a DNS-rebinding page sends: its own name, resolved to 127.0.0.1.
        assertThat(rawStatusLine("GET /api/scene HTTP/1.1\r\nHost: evil.example:" + port()
                + "\r\nConnection: close\r\n\r\n")).isEqualTo("HTTP/1.1 403 Forbidden");
        // HTTP/1.1 requires a Host: recent JDK 17 updates (17.0.21) refuse a request without one
        // with 400 before it reaches the guard, older ones pass it on and the guard says 403.
        assertThat(rawStatusLine("GET / HTTP/1.1\r\nConnection: close\r\n\r\n"))
                .as("no Host at all").isIn("HTTP/1.1 403 Forbidden", "HTTP/1.1 400 Bad Request");
    }

    @Test
    void refusesARequestFromAnotherOrigin() throws Exception {
        byte[] scene = Files.readAllBytes(TICK1_XML);
        assertThat(send(upload("/api/scene", "tick1.xml", scene)).statusCode()).as("from its own page").isEqualTo(200);

        HttpResponse<byte[]> foreign =
                send(upload("/api/scene", "tick1.xml", scene).header("Origin", "http://evil.example"));
        assertThat(foreign.statusCode()).isEqualTo(403);
        assertThat(send(get("/api/render").header("Origin", "null")).statusCode()).isEqualTo(403);
    }

    @Test
    void refusesARequestAnotherSitesPageMadeWithoutAnOrigin() throws Exception {
        // A browser sends no Origin with an <img> or <script> fetch, but says who asked.
        assertThat(send(get("/api/render").header("Sec-Fetch-Site", "cross-site").header("Sec-Fetch-Mode", "no-cors"))
                .statusCode()).isEqualTo(403);
        assertThat(send(get("/").header("Sec-Fetch-Site", "cross-site").header("Sec-Fetch-Mode", "navigate"))
                .statusCode()).as("following a link to the page is fine").isEqualTo(200);
    }

    @Test
    void describesTheCommandLinesSceneInTheTicksCoordinates() throws Exception {
        HttpResponse<byte[]> response = send(get("/api/scene"));
        assertThat(response.statusCode()).isEqualTo(200);
        assertThat(text(response)).isEqualTo("{\"name\":\"scenes/tick1.xml\",\"warnings\":[],\"ambient\":\"#555555\","
                + "\"light\":{\"position\":[1.0,3.0,2.0],\"colour\":\"#B3DDFF\",\"intensity\":120.0},"
                + "\"spheres\":[{\"position\":[0.55,-0.16,3.5],\"radius\":0.5,\"colour\":\"#0071BC\"},"
                + "{\"position\":[-0.55,0.0,5.0],\"radius\":0.9,\"colour\":\"#FF1D25\"}]}");
    }

    /** The PNG of a render's answer, {@code {"png": base64}} after any spaces sent while it rendered. */
    private static byte[] png(HttpResponse<byte[]> response) {
        Matcher answer = Pattern.compile("\\s*\\{\"png\":\"([A-Za-z0-9+/=]*)\"}").matcher(text(response));
        assertThat(answer.matches()).as("a render's answer: %s", text(response)).isTrue();
        return Base64.getDecoder().decode(answer.group(1));
    }

    @Test
    void rendersAnUploadWithTheCommandLinesRenderer() throws Exception {
        HttpResponse<byte[]> response = send(upload("/api/render", "tick1.xml", Files.readAllBytes(TICK1_XML)));
        assertThat(response.statusCode()).isEqualTo(200);
        assertThat(response.headers().firstValue("Content-Type")).hasValue("application/json; charset=utf-8");

        BufferedImage served = ImageIO.read(new ByteArrayInputStream(png(response)));
        BufferedImage expected = new ReferenceRenderer(640, 480).render(new SceneLoader(TICK1_XML, false).getScene());
        assertThat(ImageDifference.between(expected, served).differingPixels()).isZero();
    }

    @Test
    void answersABadUploadWithTheLoadersMessageForAFileOfTheSameName() throws Exception {
        String xml = "<scene>\n  <sphere colour=\"#12345\"/>\n</scene>\n";
        Path file = dir.resolve("bad.xml");
        Files.writeString(file, xml);
        String fromFile = "";
        try {
            new SceneLoader(file, false);
        } catch (SceneException e) {
            fromFile = e.getMessage();
        }

        for (String path : new String[] {"/api/scene", "/api/render"}) {
            HttpResponse<byte[]> response = send(upload(path, "bad.xml", xml.getBytes(StandardCharsets.UTF_8)));
            assertThat(response.statusCode()).as(path).isEqualTo(422);
            assertThat(text(response)).as(path)
                    .isEqualTo(SceneJson.error(fromFile.replace(file.toString(), "bad.xml")));
        }
    }

    @Test
    void refusesAnUploadLargerThanTheLoadersLimitWithoutReadingIt() throws IOException {
        long tooLarge = SceneLoader.MAX_FILE_BYTES + 1;
        assertThat(rawStatusLine("POST /api/scene?name=big.xml HTTP/1.1\r\nHost: 127.0.0.1:" + port()
                + "\r\nContent-Length: " + tooLarge + "\r\nConnection: close\r\n\r\n"))
                .isEqualTo("HTTP/1.1 413 Request Entity Too Large");
    }

    @Test
    void saysSoWhenNoSceneWasNamedOnTheCommandLine() throws Exception {
        try (PreviewServer empty = PreviewServer.start(null, 0)) {
            HttpResponse<byte[]> response = http.send(HttpRequest.newBuilder(empty.uri().resolve("/api/scene")).build(),
                    HttpResponse.BodyHandlers.ofByteArray());
            assertThat(response.statusCode()).isEqualTo(404);
        }
    }

    @Test
    void theUploadNameCannotInjectIntoTheJson() throws Exception {
        URI uri = server.uri().resolve("/api/scene?name=%22%0A%7D.xml");
        HttpResponse<byte[]> response = send(HttpRequest.newBuilder(uri)
                .POST(HttpRequest.BodyPublishers.ofString("<scene/>")));
        assertThat(response.statusCode()).isEqualTo(200);
        assertThat(text(response)).startsWith("{\"name\":\"\\\"?}.xml\",");
    }
    @Test
    void stalledConnectionsDoNotHoldUpThePage() throws Exception {
        List<Socket> stalled = new ArrayList<>();
        try {
            for (int i = 0; i < PreviewServer.CONCURRENT_RENDERS + 4; i++) {
                Socket socket = new Socket("127.0.0.1", port());
                String request = i % 2 == 0
                        ? "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + port() + "\r\nX-Half: "    // headers never end
                        : "POST /api/scene?name=a.xml HTTP/1.1\r\nHost: 127.0.0.1:" + port() + "\r\nOrigin: "
                                // The body never ends.
                                + "http://127.0.0.1:" + port() + "\r\nContent-Length: 1000\r\n\r\n<scene>";
                socket.getOutputStream().write(request.getBytes(StandardCharsets.ISO_8859_1));
                socket.getOutputStream().flush();
                stalled.add(socket);
            }
            // Not a timing check: a bound on how long to wait for a server that may hang.
            HttpResponse<byte[]> page = send(get("/").timeout(Duration.ofSeconds(
                    10L * PreviewServer.REQUEST_DEADLINE_SECONDS)));
            assertThat(page.statusCode()).isEqualTo(200);
        } finally {
            for (Socket socket : stalled) {
                socket.close();
            }
        }
    }

    @Test
    void aSceneOverTheRenderBudgetGetsOneClearMessageAndNoRender() throws Exception {
        int spheres = (int) (PreviewServer.RENDER_BUDGET / (640 * 480)) + 1;
        StringBuilder xml = new StringBuilder("<scene>\n<point-light x=\"0\" y=\"5\" z=\"0\" colour=\"#FFFFFF\"/>\n");
        for (int i = 0; i < spheres; i++) {
            xml.append("<sphere x=\"").append(i % 100).append("\" y=\"").append(i / 100)
                    .append("\" z=\"50\" colour=\"#FF0000\"/>\n");
        }
        xml.append("</scene>\n");
        HttpResponse<byte[]> response = send(upload("/api/render", "crowd.xml",
                xml.toString().getBytes(StandardCharsets.UTF_8)));
        assertThat(response.statusCode()).isEqualTo(422);
        assertThat(text(response)).isEqualTo("{\"error\":\"crowd.xml: " + spheres + " spheres at 640 x 480 is more "
                + "than the previewer renders (at most " + (spheres - 1) + " spheres); render it with tick1 --input "
                + "instead\"}");
    }

    @Test
    void aRenderWhoseClientHasGoneIsStopped() throws Exception {
        // Concentric spheres: every ray meets every sphere's bounds, so this render, within the
        // budget, would take longer than the render deadline.
        int spheres = (int) (PreviewServer.RENDER_BUDGET / (640 * 480));
        StringBuilder xml = new StringBuilder("<scene>\n<point-light x=\"0\" y=\"5\" z=\"0\" colour=\"#FFFFFF\"/>\n");
        for (int i = 0; i < spheres; i++) {
            xml.append("<sphere z=\"100\" radius=\"").append(1 + i * 0.001).append("\" colour=\"#FF0000\"/>\n");
        }
        xml.append("</scene>\n");
        byte[] scene = xml.toString().getBytes(StandardCharsets.UTF_8);
        int abandonedBefore = PreviewServer.rendersAbandoned();

        try (Socket socket = new Socket("127.0.0.1", port())) {
            OutputStream out = socket.getOutputStream();
            out.write(("POST /api/render?name=onion.xml HTTP/1.1\r\nHost: 127.0.0.1:" + port() + "\r\nOrigin: "
                    + "http://127.0.0.1:" + port() + "\r\nContent-Length: " + scene.length + "\r\n\r\n")
                    .getBytes(StandardCharsets.ISO_8859_1));
            out.write(scene);
            out.flush();
            // The answer has begun: the status line, then spaces while the render runs.
            InputStream in = socket.getInputStream();
            assertThat(new String(in.readNBytes(15), StandardCharsets.ISO_8859_1)).isEqualTo("HTTP/1.1 200 OK");
        }

        // Not a timing check: a bound on how long to wait for a server that never notices.
        long giveUp = System.nanoTime() + Duration.ofSeconds(PreviewServer.RENDER_DEADLINE_SECONDS).toNanos();
        while (PreviewServer.rendersAbandoned() == abandonedBefore && System.nanoTime() < giveUp) {
            Thread.sleep(50);
        }
        assertThat(PreviewServer.rendersAbandoned()).as("renders stopped because their client had gone")
                .isEqualTo(abandonedBefore + 1);
    }
}
