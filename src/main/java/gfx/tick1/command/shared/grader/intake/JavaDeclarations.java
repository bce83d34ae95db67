package gfx.tick1.command.shared.grader.intake;

import java.util.Optional;

/**
 * What an untrusted Java source declares, read as javac reads it (JLS 3.3 to 3.11, 7.4): Unicode
 * escapes are translated first, then white space, comments and literals are skipped. Two questions
 * are asked of it: the package a file declares ({@code package Name ;}, with white space or comments
 * between its tokens), which the tester needs to be gfx.tick1, and the first class it declares, which
 * tells a Sphere.java from a Renderer.java whatever the file is called.
 *
 * <p>A student's file can be made to cost a scanner anything, so this one reads each file in one
 * pass: no recursion, no backtracking beyond the few characters of a keyword, and nothing beyond a
 * cap ({@link #PACKAGE_SCAN_CAP}, {@link #CLASS_SCAN_CAP}), however the file is made.
 */
public final class JavaDeclarations {

    /**
     * How far into a file the package declaration is looked for. A real file's declaration is on its
     * first lines, after a comment of a few lines at most.
     */
    public static final int PACKAGE_SCAN_CAP = 64 * 1024;

    /** How far into a file its first class is looked for; a real Sphere.java declares it in the first few lines. */
    public static final int CLASS_SCAN_CAP = 1 << 20;

    /** What a file says its package is. */
    public sealed interface PackageClause {
        /** {@code package name;}, the name with its dots and without white space or comments. */
        record Declared(String name) implements PackageClause {
        }

        /** No declaration where one may be: the file begins with something else, or is all comments. */
        record Undeclared() implements PackageClause {
        }

        /** No declaration within {@link #PACKAGE_SCAN_CAP} characters of a longer file. */
        record BeyondCap() implements PackageClause {
        }
    }

    private final String code;
    private final int limit;
    private final StringBuilder text = new StringBuilder();
    /** How far {@link #code} has been translated into {@link #text}. */
    private int translated;
    /** How many backslashes of {@link #code} come just before {@link #translated}. */
    private int backslashes;
    /** Whether the scan looked for a character beyond the cap of a longer file. */
    private boolean reachedCap;
    private int position;
    /** The characters the scan has looked at, each look counted: what a test holds to the file's length. */
    private long visits;

    private JavaDeclarations(String code, int cap) {
        this.code = code;
        this.limit = Math.min(code.length(), cap);
    }

    /** The package {@code code} declares, looked for in its first {@link #PACKAGE_SCAN_CAP} characters. */
    public static PackageClause packageOf(String code) {
        return scanning(code, PACKAGE_SCAN_CAP).packageClause();
    }

    /** The first class {@code code} declares, looked for in its first {@link #CLASS_SCAN_CAP} characters. */
    public static Optional<String> firstClassOf(String code) {
        return scanning(code, CLASS_SCAN_CAP).firstClass();
    }

    /** A scan of {@code code} that reads no further than {@code cap} characters. */
    static JavaDeclarations scanning(String code, int cap) {
        return new JavaDeclarations(code, cap);
    }

    /** How many looks at a character the questions asked so far have taken. */
    long visits() {
        return visits;
    }

    PackageClause packageClause() {
        skipSpaceAndComments();
        if (!keyword("package")) {
            return undeclared();
        }
        StringBuilder name = new StringBuilder();
        while (true) {
            skipSpaceAndComments();
            if (!identifier(name)) {
                return undeclared();
            }
            skipSpaceAndComments();
            int c = peek();
            if (c == ';') {
                return new PackageClause.Declared(name.toString());
            }
            if (c != '.') {
                return undeclared();
            }
            position++;
            name.append('.');
        }
    }

    /** No declaration in what was scanned: none at all, or none within the cap of a longer file. */
    private PackageClause undeclared() {
        return reachedCap ? new PackageClause.BeyondCap() : new PackageClause.Undeclared();
    }

    /**
     * The first identifier after the keyword {@code class} outside comments and literals, where that
     * keyword does not follow a dot ({@code Sphere.class} is a class literal, not a declaration).
     */
    Optional<String> firstClass() {
        boolean afterClass = false;
        boolean afterDot = false;
        for (int c = skipSpaceAndComments(); c != -1; c = skipSpaceAndComments()) {
            if (c == '"' || c == '\'') {
                skipLiteral(c);
                afterClass = false;
                afterDot = false;
            } else if (Character.isJavaIdentifierStart(c)) {
                StringBuilder word = new StringBuilder();
                identifier(word);
                if (afterClass) {
                    return Optional.of(word.toString());
                }
                afterClass = !afterDot && word.toString().equals("class");
                afterDot = false;
            } else {
                afterClass = false;
                afterDot = c == '.';
                position++;
            }
        }
        return Optional.empty();
    }

    /**
     * The character at the scan position after Unicode escapes, or -1 at the end of what may be
     * scanned. Escapes are translated as the scan reaches them: a backslash begins one only when
     * an even number of backslashes comes before it (JLS 3.3).
     */
    private int peek() {
        visits++;
        while (text.length() <= position && translated < limit) {
            char c = read(translated);
            int escape = c == '\\' && backslashes % 2 == 0 ? escapeAt(translated) : -1;
            if (escape < 0) {
                text.append(c);
                translated++;
                backslashes = c == '\\' ? backslashes + 1 : 0;
            } else {
                text.append((char) Integer.parseInt(code.substring(escape - 4, escape), 16));
                translated = escape;
                backslashes = 0;
            }
        }
        if (position < text.length()) {
            return text.charAt(position);
        }
        reachedCap |= limit < code.length();
        return -1;
    }

    private char read(int index) {
        visits++;
        return code.charAt(index);
    }

    /** Where the escape at {@code index} ({@code \}{@code uuu0041}) ends, or -1 when it is not one. */
    private int escapeAt(int index) {
        int i = index + 1;
        if (i >= limit || read(i) != 'u') {
            return -1;
        }
        while (i < limit && read(i) == 'u') {
            i++;
        }
        if (i + 4 > limit) {
            return -1;
        }
        for (int k = i; k < i + 4; k++) {
            if (Character.digit(read(k), 16) < 0) {
                return -1;
            }
        }
        return i + 4;
    }

    private int peekAfter() {
        position++;
        int c = peek();
        position--;
        return c;
    }

    /**
     * Skips white space (space, tab, form feed, line terminators) and comments; the character after
     * them, or -1 at the end.
     */
    private int skipSpaceAndComments() {
        while (true) {
            int c = peek();
            if (c == ' ' || c == '\t' || c == '\f' || c == '\n' || c == '\r') {
                position++;
            } else if (c == '/' && peekAfter() == '/') {
                for (position += 2; (c = peek()) != -1 && c != '\n' && c != '\r'; ) {
                    position++;
                }
            } else if (c == '/' && peekAfter() == '*') {
                position += 2;
                while ((c = peek()) != -1 && !(c == '*' && peekAfter() == '/')) {
                    position++;
                }
                if (c == -1) {
                    return -1;   // an unclosed comment: nothing follows it
                }
                position += 2;
            } else {
                return c;
            }
        }
    }

    /** Skips the literal opened by {@code quote} at the scan position: "...", '...' or a text block """...""". */
    private void skipLiteral(int quote) {
        boolean textBlock = quote == '"' && peekAfter() == '"' && peekAt(2) == '"';
        position += textBlock ? 3 : 1;
        for (int c = peek(); c != -1; c = peek()) {
            if (c == '\\') {
                position += 2;
            } else if (textBlock ? c == '"' && peekAfter() == '"' && peekAt(2) == '"' : c == quote) {
                position += textBlock ? 3 : 1;
                return;
            } else if (!textBlock && (c == '\n' || c == '\r')) {
                return;   // an unclosed literal, which javac refuses: the scan goes on with the next line
            } else {
                position++;
            }
        }
    }

    private int peekAt(int ahead) {
        position += ahead;
        int c = peek();
        position -= ahead;
        return c;
    }

    /** Reads {@code word} when it is the next token and no identifier character follows it. */
    private boolean keyword(String word) {
        int start = position;
        for (int i = 0; i < word.length(); i++, position++) {
            if (peek() != word.charAt(i)) {
                position = start;
                return false;
            }
        }
        int next = peek();
        if (next != -1 && Character.isJavaIdentifierPart(next)) {
            position = start;
            return false;
        }
        return true;
    }

    /** Appends the identifier at the scan position to {@code name}; false when there is none. */
    private boolean identifier(StringBuilder name) {
        int c = peek();
        if (c == -1 || !Character.isJavaIdentifierStart(c)) {
            return false;
        }
        while (c != -1 && Character.isJavaIdentifierPart(c)) {
            name.append((char) c);
            position++;
            c = peek();
        }
        return true;
    }
}
