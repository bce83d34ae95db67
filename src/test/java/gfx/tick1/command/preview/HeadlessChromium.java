package gfx.tick1.command.preview;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Base64;
import java.util.Comparator;
import java.util.logging.Level;
import java.util.logging.Logger;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.openqa.selenium.Dimension;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * Debian's headless Chromium, driven through its own chromedriver. Both paths are given
 * explicitly, so Selenium Manager never looks for, or downloads, a browser or a driver. Other
 * packages' page tests (the cohort report's) use it too.
 */
public final class HeadlessChromium implements AutoCloseable {

    static final Path CHROMIUM = Path.of("/usr/bin/chromium");
    static final Path CHROMEDRIVER = Path.of("/usr/bin/chromedriver");

    /**
     * Selenium's DevTools bindings lag Debian's Chromium, and it warns on every start that it has
     * none for this version. The tests drive the browser through WebDriver, not DevTools, so the
     * warning says nothing about them. (A strong reference: the logging system keeps weak ones.)
     */
    private static final Logger DEVTOOLS_VERSIONS = Logger.getLogger("org.openqa.selenium.devtools.CdpVersionFinder");

    public final ChromeDriver driver;
    private final Path profile;

    private HeadlessChromium(ChromeDriver driver, Path profile) {
        this.driver = driver;
        this.profile = profile;
    }

    public static boolean isInstalled() {
        return Files.isExecutable(CHROMIUM) && Files.isExecutable(CHROMEDRIVER);
    }

    /** Skips the calling test (a JUnit assumption, so it is reported as skipped) when there is no browser. */
    public static void assumeInstalled() {
        assumeTrue(isInstalled(), "browser test skipped: no " + CHROMIUM + " or " + CHROMEDRIVER
                + "; enable the browser tests with: apt-get install chromium chromium-driver");
    }

    /** Starts the browser; see {@link #isInstalled()}. */
    public static HeadlessChromium start() throws IOException {
        DEVTOOLS_VERSIONS.setLevel(Level.SEVERE);
        System.setProperty(ChromeDriverService.CHROME_DRIVER_EXE_PROPERTY, CHROMEDRIVER.toString());
        ChromeDriverService service = new ChromeDriverService.Builder()
                .usingDriverExecutable(CHROMEDRIVER.toFile())
                .usingAnyFreePort()
                .build();
        Path profile = Files.createTempDirectory("tick1-chromium-");
        ChromeOptions options = new ChromeOptions();
        options.setBinary(CHROMIUM.toFile());
        options.addArguments("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--no-first-run", "--user-data-dir=" + profile, "--window-size=1200,700");
        ChromeDriver driver = new ChromeDriver(service, options);
        driver.manage().window().setSize(new Dimension(1200, 700));
        return new HeadlessChromium(driver, profile);
    }

    public WebDriverWait waitUpTo(Duration timeout) {
        return new WebDriverWait(driver, timeout);
    }

    /**
     * The pixels of an {@code <img>} (at its natural size) or a {@code <canvas>} (its drawing
     * buffer) as the page itself reads them: drawn onto a 2D canvas and exported losslessly.
     */
    public BufferedImage pixelsOf(WebElement element) {
        String dataUrl = (String) driver.executeScript(
                "const source = arguments[0];"
                        + "const canvas = document.createElement('canvas');"
                        + "canvas.width = source.naturalWidth || source.width;"
                        + "canvas.height = source.naturalHeight || source.height;"
                        + "canvas.getContext('2d').drawImage(source, 0, 0);"
                        + "return canvas.toDataURL('image/png');", element);
        byte[] png = Base64.getDecoder().decode(dataUrl.substring(dataUrl.indexOf(',') + 1));
        try {
            return ImageIO.read(new ByteArrayInputStream(png));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public void close() throws IOException {
        try {
            driver.quit();
        } finally {
            try (Stream<Path> files = Files.walk(profile)) {
                files.sorted(Comparator.reverseOrder()).forEach(path -> path.toFile().delete());
            }
        }
    }
}
