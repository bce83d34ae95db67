package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.sun.net.httpserver.HttpServer;
import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.engine.image.EarlierImage;
import gfx.tick1.engine.scene.SceneLoader;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.io.Writer;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Files written to attack the loader, run through the real command line: none may read another
 * file, reach the network, expand entities, or exhaust memory, and each is refused in one line.
 */
class HostileInputTest {

    private static final String DOCTYPE_REFUSED =
            "DOCTYPE declaration: not allowed in scene files (no DTDs or entities), expected <scene>";

    @TempDir
    Path dir;

    private Path output;

    @BeforeEach
    void writeAnEarlierImage() throws IOException {
        output = EarlierImage.writeTo(dir.resolve("out.png"));
    }

    private Path scene(String xml) throws IOException {
        Path scene = dir.resolve("scene.xml");
        Files.writeString(scene, xml, StandardCharsets.UTF_8);
        return scene;
    }

    private CliRun render(Path scene) {
        return CliRun.of("-i", scene.toString(), "-o", output.toString(), "--width", "8", "--height", "6");
    }

    /** The run was refused with exactly this one line, and the earlier image is untouched. */
    private void assertRefused(CliRun run, String line) throws IOException {
        assertThat(run.status()).as(run.err()).isEqualTo(RenderCommand.EXIT_BAD_SCENE);
        assertThat(run.err()).isEqualTo("tick1: " + line + System.lineSeparator());
        assertThat(Files.readAllBytes(output)).isEqualTo(EarlierImage.bytes());
    }

    /** Each template declares, in its own way, something that would pull SECRET into the scene. */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {
        "<!DOCTYPE scene [<!ENTITY xxe SYSTEM 'SECRET'>]>\n<scene><ambient-light colour='&xxe;'/></scene>",
        "<!DOCTYPE scene [<!ENTITY xxe SYSTEM 'SECRET'>]>\n<scene><sphere colour='#FF0000'>&xxe;</sphere></scene>",
        "<!DOCTYPE scene [<!ENTITY % p SYSTEM 'SECRET'> <!ENTITY % w \"<!ENTITY leak '%p;'>\"> %w;]>\n"
                + "<scene><ambient-light colour='&leak;'/></scene>",
        "<!DOCTYPE scene SYSTEM 'SECRET'>\n<scene/>",
        "<!DOCTYPE scene PUBLIC '-//x//EN' 'SECRET'>\n<scene/>"})
    void anExternalEntityNamingALocalFileNeverLeaksItsContent(String template) throws IOException {
        String secret = "top-secret-" + UUID.randomUUID();
        Path secretFile = dir.resolve("secret.txt");
        Files.writeString(secretFile, secret);
        Path scene = scene(template.replace("SECRET", secretFile.toUri().toString()));

        CliRun run = render(scene);

        assertRefused(run, scene + ":1:10: " + DOCTYPE_REFUSED);
        assertThat(run.err() + run.out()).doesNotContain(secret);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {
        "<!DOCTYPE scene [<!ENTITY xxe SYSTEM 'URL'>]>\n<scene><ambient-light colour='&xxe;'/></scene>",
        "<!DOCTYPE scene SYSTEM 'URL'>\n<scene/>",
        "<!DOCTYPE scene [<!ENTITY % p SYSTEM 'URL'> %p;]>\n<scene/>"})
    void anExternalEntityNamingAUrlIsNeverFetched(String template) throws IOException {
        AtomicInteger requests = new AtomicInteger();
        HttpServer server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0);
        server.createContext("/", exchange -> {
            requests.incrementAndGet();
            byte[] body = "#FF0000".getBytes(StandardCharsets.UTF_8);
            exchange.sendResponseHeaders(200, body.length);
            exchange.getResponseBody().write(body);
            exchange.close();
        });
        server.start();
        try {
            String url = "http://127.0.0.1:" + server.getAddress().getPort() + "/colour";
            Path scene = scene(template.replace("URL", url));

            assertRefused(render(scene), scene + ":1:10: " + DOCTYPE_REFUSED);
            assertThat(requests).as("requests the loader made").hasValue(0);
        } finally {
            server.stop(0);
        }
    }

    @Test
    void billionLaughsIsRefusedBeforeAnyExpansion() throws IOException {
        StringBuilder xml = new StringBuilder("<?xml version=\"1.0\"?>\n<!DOCTYPE scene [\n <!ENTITY l0 \"lol\">\n");
        for (int i = 1; i <= 9; i++) {
            xml.append(" <!ENTITY l").append(i).append(" \"").append(("&l" + (i - 1) + ";").repeat(10)).append("\">\n");
        }
        xml.append("]>\n<scene><ambient-light colour=\"&l9;\"/></scene>\n");
        Path scene = scene(xml.toString());

        assertRefused(render(scene), scene + ":2:10: " + DOCTYPE_REFUSED);
    }

    @Test
    void aFileOverSixtyFourMebibytesIsRefusedUnread() throws IOException {
        Path scene = dir.resolve("huge.xml");
        try (RandomAccessFile file = new RandomAccessFile(scene.toFile(), "rw")) {
            file.setLength(SceneLoader.MAX_FILE_BYTES + 1); // sparse: no disk space, no time
        }
        assertRefused(render(scene), scene + ": file is 67108865 bytes, expected at most 67108864 (64 MiB)");
    }

    @Test
    void anInputThatNeverEndsIsCutOffAtSixtyFourMebibytes() throws IOException {
        Path zero = Path.of("/dev/zero");
        assumeTrue(Files.isReadable(zero), "needs /dev/zero");
        assertRefused(render(zero), "/dev/zero: file is larger than 67108864 bytes (64 MiB)");
    }

    @Test
    void aSceneOfMoreThanAQuarterOfAMillionElementsIsRefused() throws IOException {
        Path scene = dir.resolve("many.xml");
        try (Writer out = Files.newBufferedWriter(scene)) {
            out.write("<scene>\n");
            for (int i = 0; i < SceneLoader.MAX_ELEMENTS; i++) {
                out.write("<ambient-light colour='#000000'/>\n");
            }
            out.write("</scene>\n");
        }
        // The scene element is the first; the last ambient-light is one too many.
        assertRefused(render(scene), scene + ":" + (SceneLoader.MAX_ELEMENTS + 1)
                + ":1: too many elements: scene files may have at most 250000");
    }

    @Test
    void aHugeRunOfDigitsIsRejectedWithoutBacktracking() throws IOException {
        // With an ordinary (backtracking) number pattern this takes quadratic time: hours.
        Path scene = scene("<scene><sphere z='" + "9".repeat(2_000_000) + "x' colour='#FF0000'/></scene>");
        assertRefused(render(scene), scene + ":1:16: sphere z \"9999999999999999999999999999999999999...\": "
                + "must be a decimal number such as 1.5 or -2e3");
    }

    @Test
    void warningsStopAtAHundredAndTheRestAreCounted() throws IOException {
        Path scene = scene("<scene>\n" + "<point-light colour='#FFFFFF'/>\n".repeat(151) + "</scene>\n");
        CliRun run = render(scene);
        assertThat(run.status()).as(run.err()).isZero();
        assertThat(run.err().lines()).hasSize(SceneLoader.MAX_WARNINGS + 1)
                .endsWith(scene + ": warning: 50 more warnings like these, not shown");
    }
}
