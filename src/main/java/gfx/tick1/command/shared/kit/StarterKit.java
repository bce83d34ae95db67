package gfx.tick1.command.shared.kit;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

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
    /** The folder the handout's tick1.zip unpacks to (its section 2), and the kit's folder unless told otherwise. */
    public static final String KIT_FOLDER = "tick1";

    private static final String FOLDER = "/gfx/tick1/command/shared/kit/";
    /** Where the build puts tick1's own Sphere.java and Renderer.java (see build.gradle's processResources). */
    private static final String REFERENCE = "/gfx/tick1/command/shared/javacode/reference/";
    private static final LocalDateTime ENTRY_TIME = LocalDateTime.of(2020, 1, 1, 0, 0);

    private StarterKit() {
    }

    /** The source of a starter class, such as {@code source("Vector3")}. */
    public static String source(String className) {
        return resource(className + ".java.txt");
    }

    /**
     * The course's solution of a class the student writes ({@code solution("Sphere")}, {@code solution("Renderer")}) as
     * a student hands it in: tick1's own Sphere.java or Renderer.java, which keep the starter kit's layout and which
     * the program holds beside its classes (for {@code tick1 diff}), in the starter's package {@code gfx.tick1} and
     * without the imports of tick1's own packages. With the kit's other classes it compiles into the course's program.
     */
    public static String solution(String className) {
        if (!STUDENT_CLASSES.contains(className)) {
            throw new IllegalArgumentException(className + " is not a class the student writes");
        }
        return resource(REFERENCE + className + ".java")
                .replaceFirst("(?m)^package gfx\\.tick1\\.[\\w.]+;", "package gfx.tick1;")
                .replaceAll("(?m)^import gfx\\.tick1\\.[\\w.]+;\\R", "");
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

    /**
     * Writes the kit as the handout's {@code tick1.zip}: every file under {@value #KIT_FOLDER}/, with an entry for
     * each folder, so that unpacking it gives the handout's tree. The entries carry one fixed time, so the same kit
     * makes the same bytes.
     */
    public static void writeZip(OutputStream target) throws IOException {
        ZipOutputStream zip = new ZipOutputStream(target, StandardCharsets.UTF_8);
        Set<String> folders = new LinkedHashSet<>();
        for (KitFile file : files()) {
            String path = KIT_FOLDER + "/" + file.path();
            for (int slash = path.indexOf('/'); slash >= 0; slash = path.indexOf('/', slash + 1)) {
                if (folders.add(path.substring(0, slash + 1))) {
                    zip.putNextEntry(entry(path.substring(0, slash + 1)));
                    zip.closeEntry();
                }
            }
            zip.putNextEntry(entry(path));
            zip.write(file.content().getBytes(StandardCharsets.UTF_8));
            zip.closeEntry();
        }
        zip.finish();
    }

    private static ZipEntry entry(String name) {
        ZipEntry entry = new ZipEntry(name);
        entry.setTimeLocal(ENTRY_TIME);
        return entry;
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
        try (InputStream in = StarterKit.class.getResourceAsStream(name.startsWith("/") ? name : FOLDER + name)) {
            if (in == null) {
                throw new IllegalStateException("the starter kit is missing " + name + " (a broken build)");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
