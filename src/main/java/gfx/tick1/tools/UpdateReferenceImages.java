package gfx.tick1.tools;

import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.render.GoldenImages;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Regenerates the {@link GoldenImages}: renders every {@code scenes/**.xml} at 640 x 480 into
 * {@code reference-images/} under the same relative name. Run only on purpose
 * ({@code gradle updateReferenceImages}); a commit that changes a reference image says why.
 */
public final class UpdateReferenceImages {

    private UpdateReferenceImages() {
    }

    public static void main(String[] args) throws IOException {
        Path scenes = Path.of(args.length > 0 ? args[0] : "scenes");
        Path references = Path.of(args.length > 1 ? args[1] : "reference-images");
        for (Path scene : GoldenImages.scenesUnder(scenes)) {
            Path target = GoldenImages.referenceFor(scenes, references, scene);
            Files.createDirectories(target.getParent());
            Scene loaded = new SceneLoader(scene, false).getScene();
            PngOutput.write(new ReferenceRenderer(GoldenImages.WIDTH, GoldenImages.HEIGHT).render(loaded), target);
            System.out.println("wrote " + target);
        }
    }
}
