package gfx.tick1.command.shared.cli;

import java.util.regex.Matcher;

/**
 * How the user starts tick1, for the lines that tell them what to type next: {@code tick1} for the
 * installed launcher, {@code java -jar tick1.jar} (the jar as they named it) for the students'
 * release. The JVM says which: started with {@code -jar}, its command is the jar as given, which
 * is then its whole class path.
 */
public final class Invocation {

    private Invocation() {
    }

    /** What starts this tick1: "tick1", or "java -jar " and the jar as the user named it. */
    public static String command() {
        return command(System.getProperty("sun.java.command", ""), System.getProperty("java.class.path", ""));
    }

    /** As {@link #command()}, from the JVM's command ({@code sun.java.command}) and its class path. */
    static String command(String javaCommand, String classPath) {
        boolean jar = classPath.toLowerCase(java.util.Locale.ROOT).endsWith(".jar") && !classPath.isEmpty()
                && (javaCommand.equals(classPath) || javaCommand.startsWith(classPath + " "));
        if (!jar) {
            return "tick1";
        }
        boolean quoted = classPath.chars().anyMatch(Character::isWhitespace);
        return "java -jar " + (quoted ? "\"" + classPath + "\"" : classPath);
    }

    /** How to give this tick1's Java more heap: the launcher reads JAVA_OPTS, {@code java -jar} takes -Xmx. */
    public static String moreMemory() {
        return moreMemory(command());
    }

    /** As {@link #moreMemory()}, for tick1 started by this {@link #command()}. */
    static String moreMemory(String command) {
        return javaOption(command, "-Xmx...");
    }

    /** How to give this tick1's Java the option {@code option} ("-Djava.io.tmpdir=FOLDER"). */
    public static String javaOption(String option) {
        return javaOption(command(), option);
    }

    /** As {@link #javaOption(String)}, for tick1 started by this {@link #command()}. */
    static String javaOption(String command, String option) {
        return command.equals("tick1") ? "JAVA_OPTS=" + option : command.replaceFirst("^java ",
                Matcher.quoteReplacement("java " + option + " "));
    }
}
