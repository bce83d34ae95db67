package gfx.tick1.engine.render;

import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The readable renderer's image of a scene file at the golden images' size, rendered once for the
 * whole test run (its classes share one JVM): the golden image test and the tests of the fast
 * renderer, the catalogue, the ordinary scenes and the hard cases all hold their renderer to this
 * same image, so no class renders it again. Each caller gets a copy of its own to read or draw on.
 */
public final class ReferenceImages {

    private static final Map<Path, BufferedImage> RENDERED = new ConcurrentHashMap<>();

    private ReferenceImages() {
    }

    /** {@code new ReferenceRenderer(GoldenImages.WIDTH, GoldenImages.HEIGHT).render(scene as loaded)}. */
    public static BufferedImage of(Path scene) {
        // Rendered outside the map: a render shares its rows among the test run's threads, and one of them
        // may meanwhile run another class's test that asks for an image here. Two classes that ask for the
        // same scene at once may both render it; the first image kept is the one every caller gets.
        Path key = scene.toAbsolutePath().normalize();
        BufferedImage image = RENDERED.get(key);
        if (image == null) {
            BufferedImage rendered = new ReferenceRenderer(GoldenImages.WIDTH, GoldenImages.HEIGHT)
                    .render(new SceneLoader(scene, false).getScene());
            BufferedImage kept = RENDERED.putIfAbsent(key, rendered);
            image = kept == null ? rendered : kept;
        }
        return new BufferedImage(image.getColorModel(), image.copyData(null), false, null);
    }
}
