package gfx.tick1.tools;

import gfx.tick1.image.PngOutput;
import gfx.tick1.render.ReferenceRenderer;
import gfx.tick1.scene.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Regenerates the golden images: renders every {@code scenes/**.xml} at 640 x 480 into
 * {@code reference-images/} under the same relative name. Run only on purpose
 * ({@code gradle updateReferenceImages}); a commit that changes a reference image says why.
 */
public final class UpdateReferenceImages {

    /** The size of every golden image: the handout's. */
    public static final int WIDTH = 640, HEIGHT = 480;

    private UpdateReferenceImages() {
    }

    public static void main(String[] args) throws IOException {
        Path scenes = Path.of(args.length > 0 ? args[0] : "scenes");
        Path references = Path.of(args.length > 1 ? args[1] : "reference-images");
        for (Path scene : scenesUnder(scenes)) {
            Path target = referenceFor(scenes, references, scene);
            Files.createDirectories(target.getParent());
            PngOutput.write(new ReferenceRenderer(WIDTH, HEIGHT).render(new SceneLoader(scene, false).getScene()), target);
            System.out.println("wrote " + target);
        }
    }

    /** Every scene file below {@code scenes}, in a stable order. */
    public static List<Path> scenesUnder(Path scenes) throws IOException {
        try (Stream<Path> files = Files.walk(scenes)) {
            return files.filter(p -> p.toString().endsWith(".xml")).sorted().collect(Collectors.toList());
        }
    }

    /** {@code scenes/hard/x.xml} maps to {@code reference-images/hard/x.png}. */
    public static Path referenceFor(Path scenes, Path references, Path scene) {
        String relative = scenes.relativize(scene).toString();
        return references.resolve(relative.substring(0, relative.length() - ".xml".length()) + ".png");
    }
}
