package gfx.tick1.command.bench;

import gfx.tick1.command.shared.kit.StarterKit;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

/**
 * The benchmark's yardstick for a one-off render: the course's own program, which is the starter
 * kit that {@code tick1 starter} writes with a correct {@code Sphere.java} and
 * {@code Renderer.java} (tick1's own, in the starter's package: {@link StarterKit#solution}), compiled
 * with javac and run with {@code java -cp} on the same JDK, as a student runs it.
 */
final class CourseCode {

    private static final String NO_COMPILER = "this Java has no compiler (a JRE, not a JDK)";

    private CourseCode() {
    }

    /**
     * Writes the kit and the solution under {@code folder}, compiles them, and gives the command that
     * renders {@code scene} to {@code image} with them; throws with the reason it cannot.
     */
    static List<String> build(Path folder, Path scene, Path image) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new IOException(NO_COMPILER);
        }
        Path kit = folder.resolve("course-code");
        List<String> arguments = new ArrayList<>(List.of("-d", kit.resolve("classes").toString()));
        arguments.addAll(writeKit(kit, StarterKit.solution("Sphere"), StarterKit.solution("Renderer")));
        ByteArrayOutputStream messages = new ByteArrayOutputStream();
        if (javac.run(null, messages, messages, arguments.toArray(String[]::new)) != 0) {
            throw new IOException("javac failed on the course code: " + messages.toString(StandardCharsets.UTF_8));
        }
        return render(kit, scene, image);
    }

    /**
     * The course's own work on one solution, as three fresh processes a student or the course's tester starts: javac
     * of the kit in {@code kit} with {@code sphere} and {@code renderer}, then the kit's main class on each of
     * {@code scenes}, writing its image beside the classes; throws where this Java has no javac.
     */
    static List<List<String>> pipeline(Path kit, String sphere, String renderer, List<Path> scenes)
            throws IOException {
        Path javac = Path.of(System.getProperty("java.home"), "bin", "javac");
        if (!Files.isExecutable(javac)) {
            throw new IOException(NO_COMPILER);
        }
        List<String> compile = new ArrayList<>(List.of(javac.toString(), "-d", kit.resolve("classes").toString()));
        compile.addAll(writeKit(kit, sphere, renderer));
        List<List<String>> commands = new ArrayList<>(List.of(compile));
        for (Path scene : scenes) {
            commands.add(render(kit, scene, kit.resolve(scene.getFileName() + ".png")));
        }
        return commands;
    }

    /** Writes the kit with {@code sphere} and {@code renderer} under {@code kit}; the source files javac is given. */
    private static List<String> writeKit(Path kit, String sphere, String renderer) throws IOException {
        for (StarterKit.KitFile file : StarterKit.files()) {
            file.writeUnder(kit);
        }
        Files.writeString(kit.resolve(StarterKit.SOURCE_FOLDER + "Sphere.java"), sphere, StandardCharsets.UTF_8);
        Files.writeString(kit.resolve(StarterKit.SOURCE_FOLDER + "Renderer.java"), renderer, StandardCharsets.UTF_8);
        List<String> classes = new ArrayList<>(StarterKit.GIVEN_CLASSES);
        classes.addAll(StarterKit.STUDENT_CLASSES);
        List<String> sources = new ArrayList<>();
        for (String name : classes) {
            sources.add(kit.resolve(StarterKit.SOURCE_FOLDER + name + ".java").toString());
        }
        return sources;
    }

    /** The command that renders {@code scene} to {@code image} with the kit's classes. */
    private static List<String> render(Path kit, Path scene, Path image) {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        return List.of(java, "-cp", kit.resolve("classes").toString(), "gfx.tick1.Tick1", "-i", scene.toString(),
                "-o", image.toString());
    }
}
