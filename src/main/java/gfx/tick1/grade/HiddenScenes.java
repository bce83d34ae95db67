package gfx.tick1.grade;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * What the report may say about a hidden scene the student's code failed on. The student's code
 * reads the hidden scene, so any text it makes (an exception's message, its own toString) could
 * carry the scene out; the report keeps only the exception's class name and stack frames in the
 * shape Java prints them, and the reasons grade itself words.
 */
final class HiddenScenes {

    private static final String THREW = "the code threw ";
    /** A class of the JDK's, or of the student's and starter code (whose names the student chose in advance). */
    private static final Pattern CLASS_NAME =
            Pattern.compile("(java|javax|jdk|sun|gfx\\.tick1)(\\.[A-Za-z_$][\\w$]{0,60}){1,6}");
    private static final Pattern FRAME =
            Pattern.compile("at gfx\\.tick1\\.[\\w$]{1,60}\\.[\\w$<>]{1,60}\\([\\w$]{1,60}\\.java:\\d{1,6}\\)");

    private HiddenScenes() {
    }

    /** {@code reason} without anything of the student's code's own words. */
    static String withoutMessages(String reason) {
        if (!reason.startsWith(THREW)) {
            return reason;
        }
        List<String> lines = reason.substring(THREW.length()).lines().toList();
        String first = lines.isEmpty() ? "" : lines.get(0);
        String className = first.split("[:\\s(]", 2)[0];
        List<String> kept = new ArrayList<>();
        kept.add(THREW + (CLASS_NAME.matcher(className).matches() && className.length() <= 200 ? className
                : "an exception") + " (its message is not shown for a hidden scene)");
        lines.stream().skip(1).filter(line -> FRAME.matcher(line).matches()).limit(8).forEach(kept::add);
        return String.join("\n", kept);
    }
}
