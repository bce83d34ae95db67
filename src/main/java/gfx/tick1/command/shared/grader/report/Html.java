package gfx.tick1.command.shared.grader.report;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/**
 * Text made safe for the report's pages. Names, reasons and file names come from students'
 * archives and their code's output: whatever they hold must show as text, never as markup.
 */
final class Html {

    private Html() {
    }

    /**
     * {@code text} for an element's content or a quoted attribute value: the five characters that
     * can end either are written as references, and control characters (which HTML does not allow
     * in a page, and a terminal would obey in a copied name) as U+FFFD.
     */
    static String escape(String text) {
        StringBuilder out = new StringBuilder(text.length() + 16);
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '&' -> out.append("&amp;");
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '"' -> out.append("&quot;");
                case '\'' -> out.append("&#39;");
                default -> out.append(isControl(c) ? '\uFFFD' : c);
            }
        }
        return out.toString();
    }

    /**
     * {@code text} for a plain-text file: control characters, which a terminal would obey, and the
     * bidirectional formatting characters, which can make a line read as another, as U+FFFD. (A
     * page isolates a name's direction with {@code <bdi>} instead.)
     */
    static String plain(String text) {
        StringBuilder out = new StringBuilder(text.length());
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            boolean bidi = c >= '\u202A' && c <= '\u202E' || c >= '\u2066' && c <= '\u2069';
            out.append(isControl(c) || bidi ? '\uFFFD' : c);
        }
        return out.toString();
    }

    private static boolean isControl(char c) {
        return c < 0x20 && c != '\n' && c != '\t' || c >= 0x7F && c <= 0x9F;
    }

    /**
     * A relative URL of path segments (a folder, a file name), escaped for an attribute. Each
     * segment is percent-encoded byte by byte except for letters, digits and {@code -._~}, so that
     * a {@code #}, {@code ?}, {@code /} or {@code :} in a name stays part of the name: the link
     * cannot leave the report folder or become an absolute URL.
     */
    static String relativeUrl(String... segments) {
        StringBuilder out = new StringBuilder();
        for (String segment : segments) {
            if (out.length() > 0) {
                out.append('/');
            }
            for (byte b : segment.getBytes(StandardCharsets.UTF_8)) {
                int c = b & 0xFF;
                if (c >= 'A' && c <= 'Z' || c >= 'a' && c <= 'z' || c >= '0' && c <= '9' || "-._~".indexOf(c) >= 0) {
                    out.append((char) c);
                } else {
                    out.append('%').append(Character.toUpperCase(Character.forDigit(c >> 4, 16)))
                            .append(Character.toUpperCase(Character.forDigit(c & 0xF, 16)));
                }
            }
        }
        return out.toString();
    }

    /** A resource of this package (the pages' style sheet and script), to be written into a page. */
    static String resource(String name) {
        try (InputStream in = Html.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("missing resource " + name + " beside " + Html.class.getName());
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
