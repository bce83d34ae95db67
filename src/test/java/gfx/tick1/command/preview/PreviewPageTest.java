package gfx.tick1.command.preview;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.Tick1;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.ResourceAccessMode;
import org.junit.jupiter.api.parallel.ResourceLock;
import org.openqa.selenium.By;
import org.openqa.selenium.Rectangle;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.support.ui.ExpectedConditions;
import picocli.CommandLine;

/**
 * The previewer's page in a real headless Chromium: scenes are dropped through the page's file
 * input, as a user picking a file does, and what the page shows is read back pixel by pixel.
 * Skipped, with a message saying how to enable them, where Chromium is not installed.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@ResourceLock(value = PreviewServerTest.RENDERS_ABANDONED, mode = ResourceAccessMode.READ)
@Order(10)   // one of the longest classes: it starts early (junit-platform.properties)
class PreviewPageTest {

    private static final Path TICK1_XML = Path.of("scenes", "tick1.xml");
    private static final Duration PATIENCE = Duration.ofSeconds(60);   // a slow shared CI machine

    private HeadlessChromium browser;
    private PreviewServer server;

    @TempDir
    Path dir;

    @BeforeAll
    void startBrowserAndServer() throws IOException {
        if (HeadlessChromium.isInstalled()) {
            browser = HeadlessChromium.start();
            server = PreviewServer.start(null, 0);
        }
    }

    @AfterAll
    void stop() throws IOException {
        if (server != null) {
            server.close();
        }
        if (browser != null) {
            browser.close();
        }
    }

    @BeforeEach
    void openThePage() {
        HeadlessChromium.assumeInstalled();
        browser.driver.get(server.uri().toString());
        // "empty": the page's script has run and found no scene named on the command line.
        browser.waitUpTo(PATIENCE).until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-status", "empty"));
    }

    /** Picks {@code file} with the page's file input and waits until its ray-traced image is shown. */
    private void dropAndWaitForTheViews(Path file) {
        pick(file);
        browser.waitUpTo(PATIENCE).until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-rendered",
                file.getFileName().toString()));
    }

    private void pick(Path file) {
        browser.driver.findElement(By.id("file")).sendKeys(file.toAbsolutePath().toString());
    }

    private WebElement element(String css) {
        return browser.driver.findElement(By.cssSelector(css));
    }

    private static Scene tick1Scene() {
        return new SceneLoader(TICK1_XML, false).getScene();
    }

    /** A colour of the scene file as 0xRRGGBB: the loader made each channel k / 255.0. */
    private static int rgb(Vector3 colour) {
        return (int) Math.round(colour.x * 255) << 16 | (int) Math.round(colour.y * 255) << 8
                | (int) Math.round(colour.z * 255);
    }

    private static int count(BufferedImage image, int rgb) {
        int count = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                count += (image.getRGB(x, y) & 0xFFFFFF) == rgb ? 1 : 0;
            }
        }
        return count;
    }

    @Test
    void theThreeDViewIsNotBlankAndShowsEverySphereShadedInItsColour() {
        dropAndWaitForTheViews(TICK1_XML);
        BufferedImage view = browser.pixelsOf(element("#view canvas"));

        int pixels = view.getWidth() * view.getHeight();
        int background = count(view, 0x555555);
        assertThat(pixels - background).as("pixels of the 3D view that are not its grey background")
                .isGreaterThan(pixels / 50);
        for (Sphere sphere : tick1Scene().getObjects()) {
            double[] shades = shadesOf(view, rgb(sphere.getColour()));
            assertThat(shades.length).as("pixels of the 3D view in a shade of the colour of %s", sphere)
                    .isGreaterThan(100);
            // Lit from one side, a sphere goes from a dark shade to a bright one: a flat disc would be one shade.
            assertThat(shades[shades.length - 1] - shades[0])
                    .as("the range of brightness of %s in the 3D view, as a fraction of its colour", sphere)
                    .isGreaterThan(0.3);
        }
    }

    /**
     * The brightness, sorted, of each pixel that is a shade of {@code rgb}: its channels in the colour's proportions
     * (within a few levels), as lighting scales a colour; a pixel where lighting has saturated a channel is left out.
     */
    private static double[] shadesOf(BufferedImage image, int rgb) {
        int[] colour = {rgb >> 16 & 0xFF, rgb >> 8 & 0xFF, rgb & 0xFF};
        int brightest = Math.max(colour[0], Math.max(colour[1], colour[2]));
        java.util.List<Double> shades = new java.util.ArrayList<>();
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int p = image.getRGB(x, y);
                int[] pixel = {p >> 16 & 0xFF, p >> 8 & 0xFF, p & 0xFF};
                double k = (double) Math.max(pixel[0], Math.max(pixel[1], pixel[2])) / brightest;
                boolean proportional = k > 0.05;
                for (int c = 0; c < 3 && proportional; c++) {
                    proportional = pixel[c] < 255 && Math.abs(pixel[c] - k * colour[c]) <= 12;
                }
                if (proportional && (p & 0xFFFFFF) != 0x555555) {
                    shades.add(k);
                }
            }
        }
        return shades.stream().mapToDouble(Double::doubleValue).sorted().toArray();
    }

    @Test
    void theCameraViewShowsEachSpheresColourWhereItsCentreProjects() {
        dropAndWaitForTheViews(TICK1_XML);
        BufferedImage inset = browser.pixelsOf(element("#camera-view"));
        assertThat(inset.getWidth() * 3).as("the camera view's aspect ratio is the tick's 4:3")
                .isEqualTo(inset.getHeight() * 4);

        // The tick's pinhole camera: the image plane at z = 1 spans 2 tan(22.5 degrees) across and
        // 3/4 of that down; a point C lands at (C.x / C.z, C.y / C.z) on it.
        double halfWidth = Math.tan(Math.toRadians(45) / 2), halfHeight = halfWidth * 3 / 4;
        Scene scene = tick1Scene();
        for (Sphere sphere : scene.getObjects()) {
            Vector3 C = SphereGeometry.centre(sphere);
            // The test means something only where the ray tracer itself sees this sphere there.
            Ray towardsCentre = new Ray(new Vector3(0), C.normalised());
            assertThat(scene.findClosestIntersection(towardsCentre).getObjectHit()).isSameAs(sphere);

            int x = (int) ((1 + C.x / C.z / halfWidth) / 2 * inset.getWidth());
            int y = (int) ((1 - C.y / C.z / halfHeight) / 2 * inset.getHeight());
            assertThat(String.format("#%06X", inset.getRGB(x, y) & 0xFFFFFF))
                    .as("camera view at (%d, %d), where the centre of %s projects", x, y, sphere)
                    .isEqualTo(String.format("#%06X", rgb(sphere.getColour())));
        }
    }

    @Test
    void theRayTracedPanelHasExactlyTheCommandLinesPixels() throws IOException {
        dropAndWaitForTheViews(TICK1_XML);
        BufferedImage shown = browser.pixelsOf(element("#raytraced"));

        ByteArrayOutputStream png = new ByteArrayOutputStream();
        CommandLine cli = Tick1.commandLine(new RenderCommand(png));
        cli.setErr(new PrintWriter(new StringWriter()));
        assertThat(cli.execute("--quiet", "--input", TICK1_XML.toString(), "--output", "-")).isZero();
        BufferedImage fromCli = ImageIO.read(new ByteArrayInputStream(png.toByteArray()));

        ImageDifference difference = ImageDifference.between(fromCli, shown);
        assertThat(difference.differingPixels()).as("ray-traced panel against `tick1 -o -`: %s", difference.summary())
                .isZero();
    }

    @Test
    void aBrokenSceneShowsTheCommandLinesErrorMessage() throws IOException {
        Path broken = dir.resolve("broken.xml");
        Files.writeString(broken, "<scene>\n  <sphere x=\"0\" z=\"4\" radius=\"-1\" colour=\"#FF0000\"/>\n</scene>\n");
        StringWriter err = new StringWriter();
        CommandLine cli = Tick1.commandLine(new RenderCommand(new ByteArrayOutputStream()));
        cli.setErr(new PrintWriter(err, true));
        assertThat(cli.execute("--input", broken.toString(), "--output", dir.resolve("out.png").toString()))
                .isEqualTo(RenderCommand.EXIT_BAD_SCENE);
        // The CLI names itself and the file as it was given; the page knows only the dropped file's name.
        String said = err.toString().strip();
        assertThat(said).startsWith("tick1: ");
        String expected = said.substring("tick1: ".length()).replace(broken.toString(), "broken.xml");

        pick(broken);
        browser.waitUpTo(PATIENCE).until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-status", "error"));

        assertThat(expected).startsWith("broken.xml:2:");
        assertThat(element("#message").getText()).isEqualTo(expected);
        assertThat(element("#raytraced").getAttribute("src")).as("no stale image beside the error").isNull();
    }

    @Test
    void aLaterDropReplacesTheScene() {
        dropAndWaitForTheViews(Path.of("scenes", "basic_scene.xml"));
        dropAndWaitForTheViews(TICK1_XML);

        assertThat(element("#scene-name").getText()).isEqualTo("tick1.xml");
        BufferedImage inset = browser.pixelsOf(element("#camera-view"));
        assertThat(count(inset, 0xFF0000)).as("basic_scene.xml's red sphere is gone from the camera view").isZero();
        assertThat(count(inset, 0xFF1D25)).as("tick1.xml's red sphere is in the camera view").isPositive();
    }

    @Test
    void theSceneNamedOnTheCommandLineIsShownWhenThePageOpens() throws IOException {
        try (PreviewServer withScene = PreviewServer.start(TICK1_XML, 0)) {
            browser.driver.get(withScene.uri().toString());
            browser.waitUpTo(PATIENCE).until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-rendered",
                    TICK1_XML.toString()));
            assertThat(element("#scene-name").getText()).isEqualTo(TICK1_XML.toString());
            assertThat(browser.pixelsOf(element("#raytraced")).getWidth()).isEqualTo(PreviewServer.IMAGE_WIDTH);
        }
    }

    @Test
    void withNoSceneBothPanelsSayHowToLoadOne() {
        for (String panel : new String[] {"#camera-view-hint", "#raytraced-hint"}) {
            assertThat(element(panel).isDisplayed()).as("%s on the empty page", panel).isTrue();
            assertThat(element(panel).getText()).as(panel).contains("No scene loaded", "drop a scene file");
        }
        dropAndWaitForTheViews(TICK1_XML);
        for (String panel : new String[] {"#camera-view-hint", "#raytraced-hint"}) {
            assertThat(element(panel).isDisplayed()).as("%s once a scene is shown", panel).isFalse();
        }
    }

    @Test
    void theAxesAreLabelledAtTheirArrows() {
        dropAndWaitForTheViews(TICK1_XML);
        BufferedImage view = browser.pixelsOf(element("#view canvas"));
        int[][] axes = {{'x', 0xFF2020}, {'y', 0x20E020}, {'z', 0x2040FF}};
        for (int[] axis : axes) {
            WebElement label = element(".axis-label[data-axis='" + (char) axis[0] + "']");
            assertThat(label.isDisplayed()).as("label of the %s axis", (char) axis[0]).isTrue();
            assertThat(label.getText()).startsWith(String.valueOf((char) axis[0]));
            Rectangle at = label.getRect();
            int near = countWithin(view, axis[1], at.x - 30, at.y - 30, at.x + at.width + 30, at.y + at.height + 30);
            assertThat(near).as("pixels of the %s arrow's colour near its label at %s", (char) axis[0], at.getPoint())
                    .isPositive();
        }
    }

    @Test
    void theWarningsLeaveTheLightInSight() throws IOException {
        // Eight warnings (attributes the format does not know) under a light of a colour of its own.
        StringBuilder xml = new StringBuilder("<scene>\n  <ambient-light colour=\"#333333\"/>\n"
                + "  <point-light x=\"1\" y=\"3\" z=\"2\" colour=\"#00FFFF\" intensity=\"120\"/>\n");
        for (int i = 0; i < 8; i++) {
            xml.append("  <sphere x=\"").append(i - 4).append("\" y=\"0\" z=\"6\" radius=\"0.4\" "
                    + "colour=\"#FF1D25\" raduis=\"1\"/>\n");
        }
        Path warned = Files.writeString(dir.resolve("warned.xml"), xml.append("</scene>\n").toString());
        dropAndWaitForTheViews(warned);

        WebElement message = element("#message");
        assertThat(message.getText().lines()).as("the warnings shown").hasSize(8);
        Rectangle box = message.getRect();
        BufferedImage view = browser.pixelsOf(element("#view canvas"));
        int light = count(view, 0x00FFFF);
        assertThat(light).as("pixels of the light's sun in the 3D view").isGreaterThan(20);
        assertThat(countWithin(view, 0x00FFFF, box.x, box.y, box.x + box.width, box.y + box.height))
                .as("pixels of the light under the warnings box at %s", box).isZero();
    }

    private static int countWithin(BufferedImage image, int rgb, int x0, int y0, int x1, int y1) {
        int count = 0;
        for (int y = Math.max(0, y0); y < Math.min(image.getHeight(), y1); y++) {
            for (int x = Math.max(0, x0); x < Math.min(image.getWidth(), x1); x++) {
                count += (image.getRGB(x, y) & 0xFFFFFF) == rgb ? 1 : 0;
            }
        }
        return count;
    }
}
