package gfx.tick1.command.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The installed launcher's choice of JIT (config/launcher/small-frame.sh): the first tier alone for
 * runs over before the second tier's compilations would pay, both tiers for the rest.
 */
class LauncherJitTest {
    private static final Path SHELL = Path.of("/bin/sh");
    private static final Path LINES = Path.of("config", "launcher", "small-frame.sh").toAbsolutePath();
    private static final String FIRST_TIER_ONLY = "-XX:TieredStopAtLevel=1";

    /** The JVM options the launcher's lines add for a run with {@code arguments}. */
    private static String optionsFor(String... arguments) throws IOException, InterruptedException {
        assumeTrue(Files.isExecutable(SHELL), "needs a POSIX shell at /bin/sh, as the installed launcher does");
        List<String> command = new ArrayList<>(List.of(SHELL.toString(), "-c",
                "DEFAULT_JVM_OPTS=; . \"$0\"; printf '%s' \"$DEFAULT_JVM_OPTS\"", LINES.toString()));
        command.addAll(List.of(arguments));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String said = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(process.waitFor()).as("the shell's exit status; it said: %s", said).isZero();
        return said;
    }

    @Test
    void aDiffRunsOnTheFirstTierAlone() throws IOException, InterruptedException {
        assertThat(optionsFor("diff", "Sphere.java", "Renderer.java")).as("the options of a diff")
                .contains(FIRST_TIER_ONLY);
    }

    @Test
    void aRenderOfTheHandoutsFrameRunsOnTheFirstTierAlone() throws IOException, InterruptedException {
        assertThat(optionsFor("-i", "basic_scene.xml")).as("the options of a 640 x 480 render")
                .contains(FIRST_TIER_ONLY);
    }

    @Test
    void aGradeOfOneStudentsFilesRunsOnTheFirstTierAlone() throws IOException, InterruptedException {
        assertThat(optionsFor("grade", "--sphere", "Sphere.java", "--renderer", "Renderer.java"))
                .as("the options of one student's grade").contains(FIRST_TIER_ONLY);
    }

    @Test
    void aCohortsGradeKeepsTheSecondTier() throws IOException, InterruptedException {
        assertThat(optionsFor("grade", "--submissions", "download.zip", "--jobs", "2"))
                .as("the options of a cohort's grade").doesNotContain(FIRST_TIER_ONLY);
        assertThat(optionsFor("grade", "--submissions=download.zip"))
                .as("the options of a cohort's grade, its option written with =").doesNotContain(FIRST_TIER_ONLY);
    }

    @Test
    void aGradeOfOneStudentAtAFrameOverTheLimitKeepsTheSecondTier() throws IOException, InterruptedException {
        assertThat(optionsFor("grade", "--sphere", "Sphere.java", "--renderer", "Renderer.java", "--width", "8000",
                "--height", "8000")).as("the options of a grade at 8000 x 8000").doesNotContain(FIRST_TIER_ONLY);
    }

    @Test
    void aRenderOfAFrameOverTheLimitKeepsTheSecondTier() throws IOException, InterruptedException {
        assertThat(optionsFor("-i", "basic_scene.xml", "--width", "8000", "--height", "8000"))
                .as("the options of an 8000 x 8000 render").doesNotContain(FIRST_TIER_ONLY);
    }
}
