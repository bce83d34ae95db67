package gfx.tick1.command.shared.grader.harness;

/**
 * The package a Java source file declares, found as javac finds it (JLS 3.3 to 3.11, 7.4): Unicode
 * escapes are translated first, then white space and comments are skipped, then
 * {@code package Name ;} is read, with white space or comments between its tokens. One pass over
 * at most {@link #SCAN_CAP} characters, with no recursion and no backtracking, so that no file can
 * cost the grader more than that one pass, however it is made. Needs only the JDK.
 */
final class PackageDeclaration {

    /**
     * How far into a file the declaration is looked for. A real file's declaration is on its first
     * lines, after a comment of a few lines at most.
     */
    static final int SCAN_CAP = 64 * 1024;

    /** What the scan found. */
    enum Kind { DECLARED, NONE, BEYOND_CAP }

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

    private PackageDeclaration(String code) {
        this.code = code;
        this.limit = Math.min(code.length(), SCAN_CAP);
    }

    /** The kind of what {@code code} begins with, and the package name when it declares one. */
    record Found(Kind kind, String name) {
    }

    static Found in(String code) {
        return new PackageDeclaration(code).scan();
    }

    private Found scan() {
        skipSpaceAndComments();
        if (!keyword("package")) {
            return none();
        }
        StringBuilder name = new StringBuilder();
        while (true) {
            skipSpaceAndComments();
            if (!identifier(name)) {
                return none();
            }
            skipSpaceAndComments();
            int c = peek();
            if (c == ';') {
                return new Found(Kind.DECLARED, name.toString());
            }
            if (c != '.') {
                return none();
            }
            position++;
            name.append('.');
        }
    }

    /** No declaration in what was scanned: none at all, or none within the cap of a longer file. */
    private Found none() {
        return new Found(reachedCap ? Kind.BEYOND_CAP : Kind.NONE, null);
    }

    /**
     * The character at the scan position after Unicode escapes, or -1 at the end of what may be
     * scanned. Escapes are translated as the scan reaches them: a backslash begins one only when
     * an even number of backslashes comes before it (JLS 3.3).
     */
    private int peek() {
        while (text.length() <= position && translated < limit) {
            char c = code.charAt(translated);
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

    /** Where the escape at {@code index} ({@code \}{@code uuu0041}) ends, or -1 when it is not one. */
    private int escapeAt(int index) {
        int i = index + 1;
        if (i >= limit || code.charAt(i) != 'u') {
            return -1;
        }
        while (i < limit && code.charAt(i) == 'u') {
            i++;
        }
        if (i + 4 > limit) {
            return -1;
        }
        for (int k = i; k < i + 4; k++) {
            if (Character.digit(code.charAt(k), 16) < 0) {
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

    /** Skips white space (space, tab, form feed, line terminators) and comments. */
    private void skipSpaceAndComments() {
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
                    return;   // an unclosed comment: nothing follows it
                }
                position += 2;
            } else {
                return;
            }
        }
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
