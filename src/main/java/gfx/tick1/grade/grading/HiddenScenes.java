package gfx.tick1.grade.grading;

import gfx.tick1.grade.sandbox.ChildOutput;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What the report may say about a hidden scene the student's code failed on. The student's code
 * reads the hidden scene, so any text it makes (an exception's message, its own toString, a stack
 * trace it made up) could carry the scene out. The report keeps only the exception's class name
 * and stack frames in the shape Java prints them, and only names that exist before the scene is
 * read: classes of the JDK or of the compiled code, and methods and files whose names appear in
 * the sources. (What is left can still choose among those names: a few bits, like the figures.)
 */
final class HiddenScenes {

    private static final String THREW = "the code threw ";
    private static final Pattern FRAME = Pattern.compile(
            "at (gfx\\.tick1\\.[\\w$]{1,60})\\.([\\w$<>]{1,60})\\(([\\w$]{1,60})\\.java:(\\d{1,6})\\)");
    private static final Pattern LAMBDA = Pattern.compile("lambda\\$(\\w+)\\$\\d{1,4}");
    private static final Pattern WORD = Pattern.compile("[A-Za-z_$][\\w$]*");
    /** The size a PNG header claims, in StudentProcess's reason for an unusable image. */
    private static final Pattern CHOSEN_SIZE = Pattern.compile("the image is \\d+ x \\d+, expected (\\d+ x \\d+)");
    /** The exit status the program ended with, in StudentProcess's reason. */
    private static final Pattern CHOSEN_EXIT_STATUS = Pattern.compile(", with exit status -?\\d+ \\(.*\\)$");

    /** The words of the sources: the only method and file names a true stack frame can have. */
    private final Set<String> words = new HashSet<>();
    /** The compiled classes, for the names of the student's and the starter's classes. */
    private final Path classes;
    /** Each source's line count, by file name, for the line numbers a true frame can have. */
    private final java.util.Map<String, Integer> lines = new java.util.HashMap<>();

    /** Redacts with the names of {@code sources} (file name to code) and the class files in {@code classes}. */
    HiddenScenes(java.util.Map<String, String> sources, Path classes) {
        this.classes = classes;
        sources.forEach((file, code) -> {
            Matcher word = WORD.matcher(code);
            while (word.find()) {
                words.add(word.group());
            }
            lines.put(file, (int) code.lines().count());
        });
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
        List<String> reasonLines = reason.substring(THREW.length()).lines().toList();
        String first = reasonLines.isEmpty() ? "" : reasonLines.get(0);
        String className = first.split("[:\\s(]", 2)[0];
        List<String> kept = new ArrayList<>();
        kept.add(THREW + (isKnownClass(className) ? className : "an exception")
                + " (its message is not shown for a hidden scene)");
        reasonLines.stream().skip(1).filter(this::isTrueFrame).limit(8).forEach(kept::add);
        return String.join("\n", kept);
    }

    private boolean isTrueFrame(String line) {
        Matcher frame = FRAME.matcher(line);
        if (!frame.matches() || !isKnownClass(frame.group(1))) {
            return false;
        }
        String method = frame.group(2);
        Matcher lambda = LAMBDA.matcher(method);
        boolean knownMethod = method.equals("<init>") || method.equals("<clinit>") || words.contains(method)
                || lambda.matches() && (words.contains(lambda.group(1)) || lambda.group(1).equals("static"));
        Integer fileLines = lines.get(frame.group(3) + ".java");
        return knownMethod && fileLines != null && Integer.parseInt(frame.group(4)) <= fileLines;
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
