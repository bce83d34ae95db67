package gfx.tick1.command.shared.javacode;

import gfx.tick1.command.shared.kit.StarterKit;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/**
 * tick1's own Sphere.java and Renderer.java (the reference solution, as the build copies their
 * source into the program) and the starter kit's versions of them, read as {@link JavaMembers}:
 * what {@code tick1 diff} compares a student's file with, and what the look-alike check sets aside.
 */
public final class ReferenceMembers {

    private ReferenceMembers() {
    }

    /** The source of our Sphere.java or Renderer.java, as the build copies it into the program. */
    private static String ourSource(String className) {
        String name = className + ".java";
        try (InputStream in = ReferenceMembers.class.getResourceAsStream("reference/" + name)) {
            if (in == null) {
                throw new IllegalStateException("the program is missing our " + name + " (a broken build)");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Our Sphere.java or Renderer.java, parsed: tick1's reference solution of the tick. */
    public static JavaMembers ours(String className) {
        String name = className + ".java";
        try {
            return JavaMembers.parse(name, ourSource(className));
        } catch (JavaMembers.ParseException e) {
            throw new IllegalStateException("our own " + name + " does not parse: " + e.getMessage(), e);
        }
    }

    /** The course's starter version of Sphere.java or Renderer.java, as the kit hands it out. */
    public static JavaMembers starter(String className, JavaMembers ours) {
        try {
            return JavaMembers.parse(className + ".java", StarterKit.source(className), name -> ours);
        } catch (JavaMembers.ParseException e) {
            throw new IllegalStateException("the starter kit's " + className + ".java does not parse: "
                    + e.getMessage(), e);
        }
    }
}
