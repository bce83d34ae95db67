package gfx.tick1.grade.grading;

import gfx.tick1.grade.sandbox.ChildOutput;
import java.nio.file.Path;
import java.util.regex.Pattern;

/**
 * What the report may say about a hidden scene the student's code failed on. The student's code
 * reads the hidden scene, so any text it makes (an exception's message, its own toString, a stack
 * trace it made up, the line it threw from, the name of a method it chose to throw in) could
 * carry the scene out. The report keeps fixed words and the exception's class name only, when
 * that is a class of the JDK or of the compiled code. (What is left can still choose among those
 * classes, and between pass and fail: a few bits a scene.)
 */
final class HiddenScenes {

    private static final String THREW = "the code threw ";
    /** The size a PNG header claims, in StudentProcess's reason for an unusable image. */
    private static final Pattern CHOSEN_SIZE = Pattern.compile("the image is \\d+ x \\d+, expected (\\d+ x \\d+)");
    /** The exit status the program ended with, in StudentProcess's reason. */
    private static final Pattern CHOSEN_EXIT_STATUS = Pattern.compile(", with exit status -?\\d+ \\(.*\\)$");
    /** The longest reason looked at: a class name and the start of a message, as StudentHarness writes them. */
    private static final int FIRST_LINE_CAP = 1000;

    /** The compiled classes, for the names of the student's and the starter's classes. */
    private final Path classes;

    /** Redacts with the class files in {@code classes}. */
    HiddenScenes(Path classes) {
        this.classes = classes;
    }

    /**
     * {@code reason} without anything of the student's code's own words or numbers: its
     * exception's message, and the numbers it chose (an image's width and height as its PNG header
     * gives them, its exit status), any of which could carry bytes of the scene it read.
     */
    String withoutMessages(String reason) {
        if (!reason.startsWith(THREW)) {
            return CHOSEN_SIZE.matcher(CHOSEN_EXIT_STATUS.matcher(reason)
                    .replaceAll(", with an exit status of its own (System.exit, or the JVM crashed)"))
                    .replaceAll("the image is not $1");
        }
        String rest = reason.substring(THREW.length(), Math.min(reason.length(), THREW.length() + FIRST_LINE_CAP));
        String className = rest.split("[:\\s(]", 2)[0];
        return THREW + (isKnownClass(className) ? className : "an exception")
                + " (its message is not shown for a hidden scene)";
    }

    /** A class of the JDK, or one the compiler wrote (the student's and the starter's). */
    private boolean isKnownClass(String name) {
        if (!name.matches("[\\w$]{1,60}(\\.[\\w$]{1,60}){1,8}")) {
            return false;
        }
        if (name.startsWith("gfx.tick1.")) {
            return ChildOutput.isRegularFile(classes.resolve(name.replace('.', '/') + ".class"));
        }
        try {
            Class.forName(name, false, ClassLoader.getPlatformClassLoader());
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }
}
