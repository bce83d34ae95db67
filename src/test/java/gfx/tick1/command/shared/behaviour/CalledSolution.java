package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.grade.StudentSolution;
import gfx.tick1.command.shared.grader.harness.AnswerLog;
import gfx.tick1.command.shared.grader.harness.StudentCompiler;
import gfx.tick1.command.shared.kit.StarterKit;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A student's two files for the probe tests: the correct solution of the test resources, edited
 * (each edit must find its text exactly once), compiled in memory with the starter kit and probed
 * in this JVM by the harness's own {@link AnswerLog}, as the sandbox's JVM would.
 */
record CalledSolution(String sphere, String renderer) {

    static CalledSolution correct() {
        return new CalledSolution(StudentSolution.resource("Sphere.java"), StudentSolution.resource("Renderer.java"));
    }

    CalledSolution sphere(String text, String replacement) {
        return new CalledSolution(StudentSolution.replaceOnce(sphere, text, replacement), renderer);
    }

    CalledSolution renderer(String text, String replacement) {
        return new CalledSolution(sphere, StudentSolution.replaceOnce(renderer, text, replacement));
    }

    /** The correct solution with the body of intersectionWith after a, b and c written as {@code body}. */
    CalledSolution intersection(String body) {
        int from = sphere.indexOf("        // A negative discriminant");
        String end = "        // Currently returning empty RaycastHit for no intersection\n"
                + "        return new RaycastHit();\n";
        int to = sphere.indexOf(end);
        assertThat(from).as("the correct Sphere's intersection").isPositive();
        assertThat(to).isGreaterThan(from);
        return new CalledSolution(sphere.substring(0, from) + body + sphere.substring(to + end.length()), renderer);
    }

    /** The correct solution with the body of illuminate after n is read written as {@code body}. */
    CalledSolution shading(String body) {
        int from = renderer.indexOf("        // L and V, unit vectors");
        String end = "return ambient.add(diffuse).add(specular);\n";
        int to = renderer.indexOf(end);
        assertThat(from).as("the correct Renderer's shading").isPositive();
        assertThat(to).isGreaterThan(from);
        return new CalledSolution(sphere, renderer.substring(0, from) + body + renderer.substring(to + end.length()));
    }

    /** The probes' log of these two files. */
    String probeLog(Path folder) throws Exception {
        List<StudentCompiler.Source> sources = new ArrayList<>();
        sources.add(new StudentCompiler.Source("Sphere", "Sphere.java", sphere));
        sources.add(new StudentCompiler.Source("Renderer", "Renderer.java", renderer));
        for (String given : StarterKit.GIVEN_CLASSES) {
            sources.add(new StudentCompiler.Source(given, given + ".java", StarterKit.source(given)));
        }
        StudentCompiler.Result compiled = new StudentCompiler().compile(sources);
        assertThat(compiled.errors()).as("the solution compiles").isEmpty();
        Path log = Files.createTempFile(folder, "probes", ".log");
        Files.delete(log);
        AnswerLog.write(new InMemory(compiled.classes()), log);
        return Files.readString(log);
    }

    /** What the behaviour comparison finds of these two files. */
    BehaviourFindings findings(Path folder) throws Exception {
        return BehaviourFindings.of(probeLog(folder));
    }

    /** The compiled classes, loaded from memory, beside the JDK only. */
    private static final class InMemory extends ClassLoader {
        private final Map<String, byte[]> classes;

        InMemory(Map<String, byte[]> classes) {
            super(ClassLoader.getPlatformClassLoader());
            this.classes = classes;
        }

        @Override
        protected Class<?> findClass(String name) throws ClassNotFoundException {
            byte[] bytes = classes.get(name);
            if (bytes == null) {
                throw new ClassNotFoundException(name);
            }
            return defineClass(name, bytes, 0, bytes.length);
        }
    }
}
