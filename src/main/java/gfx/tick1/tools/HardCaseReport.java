package gfx.tick1.tools;

import gfx.tick1.image.ImageDifference;
import gfx.tick1.image.PngOutput;
import gfx.tick1.render.Renderer;
import gfx.tick1.render.TruthRenderer;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Measures every hard case against the truth renderer and writes the pictures for
 * docs/hard-cases.md: for each {@code scenes/hard/NAME.xml}, {@code NAME-handout.png} and
 * {@code NAME-robust.png} in the image directory, and one markdown table row on standard output
 * with each method's error against the truth at the golden size (640 x 480).
 * Run it with {@code gradle hardCaseReport}.
 */
public final class HardCaseReport {

    private HardCaseReport() {
    }

    public static void main(String[] args) throws IOException {
        Path scenes = Path.of(args.length > 0 ? args[0] : "scenes/hard");
        Path images = Path.of(args.length > 1 ? args[1] : "docs/images/hard");
        Files.createDirectories(images);
        int width = UpdateReferenceImages.WIDTH, height = UpdateReferenceImages.HEIGHT;
        System.out.println("| case | handout formula vs truth | robust (default) vs truth | pictures |");
        System.out.println("| --- | --- | --- | --- |");
        for (Path file : UpdateReferenceImages.scenesUnder(scenes)) {
            String name = file.getFileName().toString().replace(".xml", "");
            Scene scene = new SceneLoader(file, false).getScene();
            BufferedImage truth = new TruthRenderer(width, height).render(scene);
            BufferedImage handout = new Renderer(width, height, Intersection.HANDOUT).render(scene);
            BufferedImage robust = new Renderer(width, height, Intersection.ROBUST).render(scene);
            PngOutput.write(handout, images.resolve(name + "-handout.png"));
            PngOutput.write(robust, images.resolve(name + "-robust.png"));
            System.out.printf("| %s | %s | %s | [handout](images/hard/%s-handout.png), [robust](images/hard/%s-robust.png) |%n",
                    name, describe(ImageDifference.between(truth, handout)),
                    describe(ImageDifference.between(truth, robust)), name, name);
        }
    }

    /** "exact", or how many pixels differ, how many by more than one level, and the worst. */
    static String describe(ImageDifference difference) {
        if (difference.differingPixels() == 0) {
            return "exact";
        }
        return String.format("%d px differ, %d by &gt; 1 level, max %d", difference.differingPixels(),
                difference.pixelsDifferingByMoreThan(1), difference.maxDifference());
    }
}
