package gfx.tick1.engine.scene;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The scene files shipped inside the program: the handout's {@code tick1.xml} and
 * {@code basic_scene.xml} (the scenes {@code diagnose} recognises) and the grading scene
 * {@code grade} uses as its hidden scene.
 */
public final class BundledScenes {

    /** The handout's task scene, the same file as scenes/tick1.xml. */
    public static final String TICK1 = "tick1.xml";
    /** The hidden grading scene. */
    public static final String HIDDEN = "hidden.xml";
    /** The scenes {@code grade} renders when not given {@code --scenes}, in order. */
    public static final List<String> GRADING = List.of(TICK1, HIDDEN);
    /** The handout's basic_scene.xml, the scene the starter kit ships (kept with the kit). */
    public static final String BASIC = "basic_scene.xml";
    /** The scenes a student renders with the kit, which {@code diagnose} recognises; tick1.xml first. */
    public static final List<String> STUDENT_SCENES = List.of(TICK1, BASIC);

    private static final String FOLDER = "/gfx/tick1/scenes/";
    private static final String KIT_FOLDER = "/gfx/tick1/command/shared/kit/";

    private BundledScenes() {
    }

    private static String resource(String name) {
        return (name.equals(BASIC) ? KIT_FOLDER : FOLDER) + name;
    }

    /** Writes the bundled scene {@code name} into {@code directory} under the same name. */
    public static Path extract(String name, Path directory) throws IOException {
        Path target = directory.resolve(name);
        try (InputStream in = BundledScenes.class.getResourceAsStream(resource(name))) {
            if (in == null) {
                throw new IOException("no bundled scene called " + name);
            }
            Files.write(target, in.readAllBytes());
        }
        return target;
    }

    /** Loads the bundled scene {@code name}; messages name it as {@code name}. */
    public static Scene load(String name) {
        try (InputStream in = BundledScenes.class.getResourceAsStream(resource(name))) {
            if (in == null) {
                throw new IOException("no bundled scene called " + name);
            }
            return new SceneLoader(name, in.readAllBytes(), true).getScene();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
