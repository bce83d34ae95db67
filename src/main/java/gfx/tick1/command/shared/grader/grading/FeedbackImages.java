package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.grading.Grading.CourseScene;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult.Images;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.io.IoErrors;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Writes the images of a wrong scene that is not hidden (a hidden one has none): the heat map,
 * the student's image and the reference, named after the scene's number and file.
 */
final class FeedbackImages {

    private final Path images;
    private final PrintWriter out;
    private final PrintWriter err;

    /** Writes into {@code images}; says where on {@code out}, and on {@code err} when it cannot. */
    FeedbackImages(Path images, PrintWriter out, PrintWriter err) {
        this.images = images;
        this.out = out;
        this.err = err;
    }

    /** The names of the three images written for scene {@code number}, or empty when they could not be. */
    Optional<Images> write(int number, CourseScene scene, BufferedImage image, ImageDifference difference,
            BufferedImage expected) {
        String stem = number + "-" + scene.name().replaceAll("[^A-Za-z0-9._-]", "_").replaceAll("\\.xml$", "");
        Images names = new Images(stem + "-diff.png", stem + "-yours.png", stem + "-expected.png");
        try {
            Files.createDirectories(images);
            PngOutput.write(difference.signedHeatMapWithLegend(), images.resolve(names.heatMap()));
            PngOutput.write(image, images.resolve(names.yours()));
            PngOutput.write(expected, images.resolve(names.expected()));
            out.println("  heat map: " + images.resolve(names.heatMap()) + " (beside it: " + names.yours() + " and "
                    + names.expected() + ")");
            return Optional.of(names);
        } catch (IOException e) {
            err.println("tick1 grade: " + images + ": cannot write the report images: " + IoErrors.describe(e));
            return Optional.empty();
        }
    }
}
