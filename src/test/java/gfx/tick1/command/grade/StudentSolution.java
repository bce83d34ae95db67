package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.kit.StarterKit;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A student's two files for the tests: the correct solution in {@code src/test/resources/students/correct},
 * or the starter kit's untouched files, with one slip edited in the way a student would make it.
 * Every edit must find its text exactly once, so that an edit can never silently do nothing.
 */
public record StudentSolution(String sphere, String renderer) {

    public static StudentSolution correct() {
        return new StudentSolution(resource("Sphere.java"), resource("Renderer.java"));
    }

    /** The kit as handed out: both files with their TODOs. */
    static StudentSolution untouchedStarterKit() {
        return new StudentSolution(StarterKit.source("Sphere"), StarterKit.source("Renderer"));
    }

    StudentSolution withStarterRenderer() {
        return new StudentSolution(sphere, StarterKit.source("Renderer"));
    }

    public StudentSolution editSphere(String text, String replacement) {
        return new StudentSolution(replaceOnce(sphere, text, replacement), renderer);
    }

    public StudentSolution editRenderer(String text, String replacement) {
        return new StudentSolution(sphere, replaceOnce(renderer, text, replacement));
    }

    /** The 1-based line of the correct solution's Sphere.java that holds {@code text}. */
    public static int sphereLineOf(String text) {
        String[] lines = resource("Sphere.java").split("\n");
        for (int i = 0; i < lines.length; i++) {
            if (lines[i].contains(text)) {
                return i + 1;
            }
        }
        throw new AssertionError(text + " is not in Sphere.java");
    }

    /** Writes the two files into {@code folder}/Sphere.java and {@code folder}/Renderer.java. */
    Path[] writeTo(Path folder) throws IOException {
        Files.createDirectories(folder);
        Path s = folder.resolve("Sphere.java"), r = folder.resolve("Renderer.java");
        Files.writeString(s, sphere);
        Files.writeString(r, renderer);
        return new Path[] {s, r};
    }

    /** {@code source} with its one {@code text} replaced; a text that is not there once fails the test. */
    public static String replaceOnce(String source, String text, String replacement) {
        int first = source.indexOf(text);
        assertThat(first).as("the edit's text \"%s\" must be in the solution", text).isNotNegative();
        assertThat(source.indexOf(text, first + 1)).as("the edit's text \"%s\" must occur once", text).isNegative();
        return source.replace(text, replacement);
    }

    /** A file of the tests' correct solution, {@code students/correct/NAME}. */
    public static String resource(String name) {
        try (InputStream in = StudentSolution.class.getResourceAsStream("/students/correct/" + name)) {
            assertThat(in).as("test resource students/correct/" + name).isNotNull();
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
