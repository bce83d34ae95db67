package gfx.tick1.scene;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The scene files shipped inside the program: the handout's {@code tick1.xml} (the default
 * scene of {@code diagnose}) and the grading scene {@code grade} uses as its hidden scene.
 */
public final class BundledScenes {

    /** The handout's task scene, the same file as scenes/tick1.xml. */
    public static final String TICK1 = "tick1.xml";
    /** The hidden grading scene. */
    public static final String HIDDEN = "hidden.xml";
    /** The scenes {@code grade} renders when not given {@code --scenes}, in order. */
    public static final List<String> GRADING = List.of(TICK1, HIDDEN);

    private static final String FOLDER = "/gfx/tick1/scenes/";

    private BundledScenes() {
    }

    /** Writes the bundled scene {@code name} into {@code directory} under the same name. */
    public static Path extract(String name, Path directory) throws IOException {
        Path target = directory.resolve(name);
        try (InputStream in = BundledScenes.class.getResourceAsStream(FOLDER + name)) {
            if (in == null) {
                throw new IOException("no bundled scene called " + name);
            }
            Files.write(target, in.readAllBytes());
        }
        return target;
    }

    /** Loads the bundled scene {@code name}; messages name it as {@code name}. */
    public static Scene load(String name) {
        try (InputStream in = BundledScenes.class.getResourceAsStream(FOLDER + name)) {
            if (in == null) {
                throw new IOException("no bundled scene called " + name);
            }
            return new SceneLoader(name, in.readAllBytes(), true).getScene();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
