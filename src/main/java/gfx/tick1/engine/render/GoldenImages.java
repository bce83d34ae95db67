package gfx.tick1.engine.render;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * The golden images: every scene file under a folder, rendered by the {@link ReferenceRenderer}
 * at the handout's size into a PNG of the same relative name under another folder
 * ({@code scenes/hard/x.xml} to {@code reference-images/hard/x.png}). The tool that writes them
 * and the tests that compare with them take the list, the size and the names from here.
 */
public final class GoldenImages {

    /** The size of every golden image: the handout's. */
    public static final int WIDTH = 640, HEIGHT = 480;

    private GoldenImages() {
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
