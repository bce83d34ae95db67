package gfx.tick1.starter;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The project's re-creation of the handout's starter code, package {@code gfx.tick1}, kept as
 * resources ({@code *.java.txt}) so that the build does not compile it into the program: the
 * classes a student does not edit, the two files a student does ({@code Sphere.java} and
 * {@code Renderer.java}, with the handout's TODOs in place of the solution), and
 * {@code basic_scene.xml}. {@code grade} compiles students' files against the first group;
 * {@code starter} hands out all of it.
 */
public final class StarterKit {

    /** The classes the student uses but does not edit, with the API of the spec's last section. */
    public static final List<String> GIVEN_CLASSES =
            List.of("Camera", "PointLight", "Ray", "RaycastHit", "Scene", "SceneLoader", "Tick1", "Vector3");
    /** The classes the student edits and submits. */
    public static final List<String> STUDENT_CLASSES = List.of("Sphere", "Renderer");
    /** Where the sources go in the kit, as in the handout's section 2. */
    public static final String SOURCE_FOLDER = "src/gfx/tick1/";
    public static final String BASIC_SCENE = "basic_scene.xml";

    private static final String FOLDER = "/gfx/tick1/starter/";

    private StarterKit() {
    }

    /** The source of a starter class, such as {@code source("Vector3")}. */
    public static String source(String className) {
        return resource(className + ".java.txt");
    }

    /** Every file of the kit, by its path inside the kit, as the handout lists them. */
    public static List<KitFile> files() {
        List<KitFile> files = new ArrayList<>();
        List<String> classes = new ArrayList<>(GIVEN_CLASSES);
        classes.addAll(STUDENT_CLASSES);
        classes.sort(null);
        for (String name : classes) {
            files.add(new KitFile(SOURCE_FOLDER + name + ".java", source(name)));
        }
        files.add(new KitFile(BASIC_SCENE, resource(BASIC_SCENE)));
        return files;
    }

    /** One file of the kit: where it goes under the kit's folder, and what it holds. */
    public record KitFile(String path, String content) {

        public void writeUnder(Path folder) throws IOException {
            Path target = folder.resolve(path);
            Files.createDirectories(target.getParent());
            Files.writeString(target, content, StandardCharsets.UTF_8);
        }
    }

    private static String resource(String name) {
        try (InputStream in = StarterKit.class.getResourceAsStream(FOLDER + name)) {
            if (in == null) {
                throw new IllegalStateException("the starter kit is missing " + name + " (a broken build)");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
