package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.engine.image.ImageDifference;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --intersection robust|stable|handout} on the main command. */
class IntersectionOptionTest {

    @TempDir
    Path dir;

    private ImageDifference robustAgainst(String method, String scene) throws IOException {
        Path robust = dir.resolve("robust.png"), other = dir.resolve(method + ".png");
        assertThat(CliRun.of("-q", "-i", scene, "-o", robust.toString()).status()).isZero();
        CliRun run = CliRun.of("-q", "-i", scene, "-o", other.toString(), "--intersection", method);
        assertThat(run.status()).as(run.err()).isZero();
        return ImageDifference.between(ImageIO.read(robust.toFile()), ImageIO.read(other.toFile()));
    }

    @Test
    void theHandoutFormulaIsSelectableAndDrawsTheHardCasesDifferently() throws IOException {
        assertThat(robustAgainst("handout", "scenes/hard/far-small-spheres.xml").differingPixels()).isPositive();
    }

    @Test
    void theMethodNameIsCaseInsensitive() throws IOException {
        // Mixed case, on a scene where the handout formula draws differently: accepted, and used.
        assertThat(robustAgainst("Handout", "scenes/hard/far-small-spheres.xml").differingPixels()).isPositive();
    }

    @Test
    void anUnknownMethodIsAUsageError() {
        CliRun run = CliRun.of("--intersection", "exact", "-o", dir.resolve("x.png").toString());
        assertThat(run.status()).isEqualTo(RenderCommand.EXIT_USAGE);
        assertThat(run.err()).contains("--intersection").contains("exact").doesNotContain("Exception");
        assertThat(run.err().lines()).hasSize(1);
    }
}
