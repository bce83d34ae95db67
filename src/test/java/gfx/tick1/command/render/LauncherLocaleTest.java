package gfx.tick1.command.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The installed launcher names any file, whatever the locale it is started in: a fresh Debian's
 * login and a container with no LANG give Java the POSIX locale, in which it cannot name "Zoë".
 */
class LauncherLocaleTest {
    private static final Path LAUNCHER = Path.of("build", "install", "tick1", "bin", "tick1").toAbsolutePath();

    @Test
    void rendersBetweenFilesNamedOutsideAsciiUnderThePosixLocale(@TempDir Path folder)
            throws IOException, InterruptedException {
        assumeTrue(Files.isExecutable(LAUNCHER), "needs tick1 installed (gradle installDist)");
        Path student = Files.createDirectories(folder.resolve("Zoë Brontë"));
        Path scene = Files.copy(Path.of("scenes", "tick1.xml"), student.resolve("scène.xml"));
        Path image = student.resolve("rendu é.png");
        ProcessBuilder run = new ProcessBuilder(LAUNCHER.toString(), "-q", "-i", scene.toString(),
                "-o", image.toString()).redirectErrorStream(true);
        Map<String, String> environment = run.environment();
        environment.keySet().removeIf(name -> name.equals("LANG") || name.startsWith("LC_"));
        environment.put("LC_ALL", "POSIX");
        Process process = run.start();
        String said = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);

        assertThat(process.waitFor()).as("exit status; it said: %s", said).isZero();
        assertThat(image).as("the image written under the POSIX locale").isNotEmptyFile();
    }
}
