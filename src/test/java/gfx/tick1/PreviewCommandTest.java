package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.preview.PreviewCommand;
import gfx.tick1.command.preview.PreviewServer;
import gfx.tick1.command.render.RenderCommand;
import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code tick1 preview}, run through the real entry point. */
class PreviewCommandTest {

    private static final Pattern ADDRESS = Pattern.compile("http://127\\.0\\.0\\.1:\\d+/");

    @Test
    void servesUntilInterruptedAfterPrintingOneLineWithItsAddress() throws Exception {
        StringWriter out = new StringWriter(), err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new RenderCommand(new ByteArrayOutputStream()));
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        CompletableFuture<Thread> runner = new CompletableFuture<>();
        CompletableFuture<Integer> status = CompletableFuture.supplyAsync(() -> {
            runner.complete(Thread.currentThread());
            return commandLine.execute("preview", "scenes/tick1.xml", "--port", "0", "--no-open");
        });
        try {
            Matcher address = ADDRESS.matcher("");
            boolean printed = false;
            for (int i = 0; i < 600 && !printed; i++) {   // up to 30 s on a slow machine
                Thread.sleep(50);
                printed = address.reset(out.toString()).find();
            }
            assertThat(printed).as("an address was printed: %s", out).isTrue();
            assertThat(out.toString()).isEqualTo("tick1 preview: scenes/tick1.xml at " + address.group()
                    + " (Ctrl-C to stop)" + System.lineSeparator());

            HttpResponse<String> scene = HttpClient.newHttpClient().send(
                    HttpRequest.newBuilder(URI.create(address.group()).resolve("/api/scene")).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertThat(scene.statusCode()).isEqualTo(200);
            assertThat(scene.body()).startsWith("{\"name\":\"scenes/tick1.xml\"");
        } finally {
            runner.get(10, TimeUnit.SECONDS).interrupt();
        }
        assertThat(status.get(10, TimeUnit.SECONDS)).isEqualTo(PreviewCommand.EXIT_STOPPED);
        assertThat(err.toString()).isEmpty();
    }

    @Test
    void aBrokenSceneFileIsServedAndItsErrorAlsoPrintedInTheTerminal(@org.junit.jupiter.api.io.TempDir
            java.nio.file.Path dir) throws Exception {
        java.nio.file.Path broken = java.nio.file.Files.writeString(dir.resolve("broken.xml"), "<scene><sphere/>");
        StringWriter out = new StringWriter(), err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new RenderCommand(new ByteArrayOutputStream()));
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        CompletableFuture<Thread> runner = new CompletableFuture<>();
        CompletableFuture<Integer> status = CompletableFuture.supplyAsync(() -> {
            runner.complete(Thread.currentThread());
            return commandLine.execute("preview", broken.toString(), "--port", "0", "--no-open");
        });
        try {
            for (int i = 0; i < 600 && !ADDRESS.matcher(out.toString()).find(); i++) {
                Thread.sleep(50);
            }
            assertThat(out.toString()).as("still served").containsPattern(ADDRESS);
            assertThat(err.toString()).startsWith("tick1 preview: " + broken + ":").endsWith("(also on the page, "
                    + "where a corrected file can be dropped)" + System.lineSeparator());
            assertThat(err.toString().lines()).hasSize(1);
        } finally {
            runner.get(10, TimeUnit.SECONDS).interrupt();
        }
        assertThat(status.get(10, TimeUnit.SECONDS)).isEqualTo(PreviewCommand.EXIT_STOPPED);
    }

    @Test
    void aMissingSceneFileStopsItWithOneLine() {
        CliRun run = CliRun.of("preview", "no/such/scene.xml", "--no-open");
        assertThat(run.status()).isEqualTo(PreviewCommand.EXIT_NO_SCENE);
        assertThat(run.err()).isEqualTo("tick1 preview: no/such/scene.xml: no such file" + System.lineSeparator());
        assertThat(run.out()).isEmpty();
    }

    @Test
    void aPortOutOfRangeIsAUsageError() {
        CliRun run = CliRun.of("preview", "--port", "70000", "--no-open");
        assertThat(run.status()).isEqualTo(PreviewCommand.EXIT_USAGE);
        assertThat(run.err()).contains("--port 70000: must be from 0 to 65535").doesNotContain("Exception");
    }

    @Test
    void aPortInUseIsAUsageError() throws Exception {
        try (PreviewServer other = PreviewServer.start(null, 0)) {
            String port = Integer.toString(other.uri().getPort());
            CliRun run = CliRun.of("preview", "--port", port, "--no-open");
            assertThat(run.status()).isEqualTo(PreviewCommand.EXIT_USAGE);
            assertThat(run.err()).startsWith("tick1 preview: cannot use port " + port + ":")
                    .contains("--port 0 for any free one");
        }
    }

    @Test
    void helpDescribesTheSubcommand() {
        CliRun run = CliRun.of("preview", "--help");
        assertThat(run.status()).isZero();
        assertThat(run.out()).contains("Usage: tick1 preview", "--port", "--no-open", "SCENE.xml");
        assertThat(CliRun.of("--help").out()).as("tick1 --help lists it").contains("preview");
    }
}
