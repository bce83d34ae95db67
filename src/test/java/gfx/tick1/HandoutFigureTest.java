package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/**
 * Fidelity to the course: our render of {@code tick1.xml} against the handout's own Figure 1,
 * read from {@code ../shared/handout-figures} when that folder exists (it is never copied in).
 * The figure was made by an older build, so the spec allows 3 levels (15,350 pixels differ).
 */
class HandoutFigureTest {

    private static final Path FIGURES = Path.of("..", "shared", "handout-figures");

    @Test
    void tick1SceneMatchesFigure1WithinThreeLevels() throws IOException {
        Path figure = FIGURES.resolve("fig1-final.png");
        assumeTrue(Files.exists(figure), "skipped: the handout's figure " + figure.getFileName()
                + " is not on this machine");
        BufferedImage expected = ImageIO.read(figure.toFile());
        BufferedImage actual = new ReferenceRenderer(640, 480)
                .render(new SceneLoader(Path.of("scenes/tick1.xml"), false).getScene());

        ImageDifference difference = ImageDifference.between(expected, actual);
        assertThat(difference.maxDifference()).as(difference.summary()).isLessThanOrEqualTo(3);
    }
}
