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

    private CourseCode() {
    }

    /**
     * Writes the kit and the solution under {@code folder}, compiles them, and gives the command that
     * renders {@code scene} to {@code image} with them; throws with the reason it cannot.
     */
    static List<String> build(Path folder, Path scene, Path image) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new IOException("this Java has no compiler (a JRE, not a JDK)");
        }
        Path kit = folder.resolve("course-code");
        for (StarterKit.KitFile file : StarterKit.files()) {
            file.writeUnder(kit);
        }
        List<String> arguments = new ArrayList<>(List.of("-d", kit.resolve("classes").toString()));
        for (String name : StarterKit.STUDENT_CLASSES) {
            Files.writeString(kit.resolve(StarterKit.SOURCE_FOLDER + name + ".java"), StarterKit.solution(name),
                    StandardCharsets.UTF_8);
        }
        List<String> classes = new ArrayList<>(StarterKit.GIVEN_CLASSES);
        classes.addAll(StarterKit.STUDENT_CLASSES);
        for (String name : classes) {
            arguments.add(kit.resolve(StarterKit.SOURCE_FOLDER + name + ".java").toString());
        }
        ByteArrayOutputStream messages = new ByteArrayOutputStream();
        if (javac.run(null, messages, messages, arguments.toArray(String[]::new)) != 0) {
            throw new IOException("javac failed on the course code: " + messages.toString(StandardCharsets.UTF_8));
        }
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        return List.of(java, "-cp", kit.resolve("classes").toString(), "gfx.tick1.Tick1", "-i", scene.toString(),
                "-o", image.toString());
    }
}
