package gfx.tick1.tools;

import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.render.GoldenImages;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.render.TruthRenderer;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Measures every hard case against the truth renderer and writes the pictures for
 * docs/hard-cases.md, at half size to keep the repository small: for each
 * {@code scenes/hard/NAME.xml}, {@code NAME.png} (the default renderer's image, 2 x 2 pixels
 * averaged) and, where the handout's formula is off by more than one level, {@code
 * NAME-handout-error.png} (a heat map of its error against the truth, the worst of each 2 x 2 so
 * that single-pixel errors stay visible). On standard output: one markdown table row per case
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
        int width = GoldenImages.WIDTH, height = GoldenImages.HEIGHT;
        System.out.println("| case | handout formula vs truth | robust (default) vs truth | pictures |");
        System.out.println("| --- | --- | --- | --- |");
        for (Path file : GoldenImages.scenesUnder(scenes)) {
            String name = file.getFileName().toString().replace(".xml", "");
            Scene scene = new SceneLoader(file, false).getScene();
            BufferedImage truth = new TruthRenderer(width, height).render(scene);
            BufferedImage robust = new ReferenceRenderer(width, height, Intersection.ROBUST).render(scene);
            ImageDifference handoutError = ImageDifference.between(truth,
                    new ReferenceRenderer(width, height, Intersection.HANDOUT).render(scene));
            PngOutput.write(halve(robust, false), images.resolve(name + ".png"));
            String pictures = "[image](images/hard/" + name + ".png)";
            if (handoutError.maxDifference() > 1) {
                PngOutput.write(halve(handoutError.heatMap(), true), images.resolve(name + "-handout-error.png"));
                pictures += ", [handout's error](images/hard/" + name + "-handout-error.png)";
            }
            System.out.printf("| %s | %s | %s | %s |%n", name, describe(handoutError),
                    describe(ImageDifference.between(truth, robust)), pictures);
        }
    }

    /** Half the size: each 2 x 2 block becomes its average, or its brightest pixel. */
    static BufferedImage halve(BufferedImage image, boolean brightest) {
        int w = image.getWidth() / 2, h = image.getHeight() / 2;
        BufferedImage half = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int[] channels = new int[3];
                int best = -1;
                for (int k = 0; k < 4; k++) {
                    int rgb = image.getRGB(2 * x + k % 2, 2 * y + k / 2) & 0xFFFFFF;
                    int sum = 0;
                    for (int c = 0; c < 3; c++) {
                        channels[c] += rgb >> (16 - 8 * c) & 0xFF;
                        sum += rgb >> (16 - 8 * c) & 0xFF;
                    }
                    if (brightest && sum > best) {
                        best = sum;
                        half.setRGB(x, y, rgb);
                    }
                }
                if (!brightest) {
                    half.setRGB(x, y, channels[0] / 4 << 16 | channels[1] / 4 << 8 | channels[2] / 4);
                }
            }
        }
        return half;
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
