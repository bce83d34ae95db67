package gfx.tick1.command.shared.grader.intake;

/**
 * The name of the first class a Java source declares, found by one linear scan that skips
 * comments, string and character literals (text blocks too): enough to tell a Sphere.java from a
 * Renderer.java whatever the file is called. A student's file is untrusted, so this neither
 * recurses nor backtracks, and reads no further than {@link #MAX_CHARS}.
 */
public final class JavaClassName {

    /** How far into a file the scan looks; a real Sphere.java declares its class in the first few lines. */
    public static final int MAX_CHARS = 1 << 20;

    private JavaClassName() {
    }

    /** The first declared class's name, or null when none is found. */
    public static String of(String source) {
        int end = Math.min(source.length(), MAX_CHARS);
        int at = 0;
        boolean afterClass = false;
        while (at < end) {
            char c = source.charAt(at);
            if (c == '/' && at + 1 < end && source.charAt(at + 1) == '/') {
                at = lineEnd(source, at, end);
            } else if (c == '/' && at + 1 < end && source.charAt(at + 1) == '*') {
                int close = source.indexOf("*/", at + 2);
                at = close < 0 || close >= end ? end : close + 2;
            } else if (c == '"' || c == '\'') {
                at = literalEnd(source, at, end);
                afterClass = false;
            } else if (Character.isJavaIdentifierStart(c)) {
                int start = at;
                while (at < end && Character.isJavaIdentifierPart(source.charAt(at))) {
                    at++;
                }
                String word = source.substring(start, at);
                if (afterClass) {
                    return word;
                }
                afterClass = word.equals("class") && !precededByDot(source, start);
            } else {
                if (!Character.isWhitespace(c)) {
                    afterClass = false;
                }
                at++;
            }
        }
        return null;
    }

    private static int lineEnd(String source, int at, int end) {
        int newline = source.indexOf('\n', at);
        return newline < 0 || newline >= end ? end : newline + 1;
    }

    /** Just after the literal opened at {@code at}: "...", '...' or a text block """...""". */
    private static int literalEnd(String source, int at, int end) {
        char quote = source.charAt(at);
        if (quote == '"' && source.startsWith("\"\"\"", at)) {
            int close = at + 3;
            while (true) {
                close = source.indexOf("\"\"\"", close);
                if (close < 0 || close >= end) {
                    return end;
                }
                if (source.charAt(close - 1) != '\\') {
                    return close + 3;
                }
                close++;
            }
        }
        int i = at + 1;
        while (i < end && source.charAt(i) != quote && source.charAt(i) != '\n') {
            i += source.charAt(i) == '\\' ? 2 : 1;
        }
        return Math.min(i + 1, end);
    }

    /** {@code Foo.class} is a class literal, not a declaration. */
    private static boolean precededByDot(String source, int at) {
        int i = at - 1;
        while (i >= 0 && Character.isWhitespace(source.charAt(i))) {
            i--;
        }
        return i >= 0 && source.charAt(i) == '.';
    }
}
