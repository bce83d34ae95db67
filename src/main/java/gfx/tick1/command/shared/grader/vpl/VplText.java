package gfx.tick1.command.shared.grader.vpl;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * Lines for VPL's comment block, made so that no text can be read by VPL as anything but what tick1 meant.
 * VPL reads a line that starts with {@code -} as a title, one that starts with blanks and {@code >} as
 * preformatted text, a line that is only {@code <|--} or {@code --|>} (blanks around) as the start or end of
 * a block, and the last line that starts {@code Grade :=>>} as the grade, even inside a block; its editor
 * splits lines at {@code \r\n}, {@code \n} and a lone {@code \r}, and hides a title's last {@code (N)}.
 * Text tick1 did not write itself (a compiler's words, an exception's, a file name) is therefore put after
 * {@code >}, with its control characters and lone carriage returns removed and VPL's tags broken first.
 */
final class VplText {

    /** A quoted line is wrapped at this many characters, so the report stays readable. */
    static final int WIDTH = 100;

    /** What VPL's editor takes off the end of a title as the title's grade: "(3)", "(-0.5)". */
    private static final Pattern TITLE_GRADE = Pattern.compile("\\(-?\\d+\\.?\\d*\\)\\s*$");

    private VplText() {
    }

    /**
     * {@code text}, which tick1 did not write, as lines after {@code >}: cleaned, tags broken, long lines
     * wrapped, and at most {@code mostLines} of them (a last line says how many were left out).
     */
    static List<String> quoted(String text, int mostLines) {
        List<String> lines = new ArrayList<>();
        for (String line : clean(text).split("\n", -1)) {
            String rest = breakTags(line.stripTrailing());
            do {
                int cut = rest.length() <= WIDTH ? rest.length() : wrapAt(rest);
                lines.add(">" + rest.substring(0, cut));
                rest = rest.substring(cut);
            } while (!rest.isEmpty());
        }
        while (lines.size() > 1 && lines.get(lines.size() - 1).equals(">")) {
            lines.remove(lines.size() - 1);
        }
        if (lines.size() > mostLines) {
            int left = lines.size() - (mostLines - 1);
            lines.subList(mostLines - 1, lines.size()).clear();
            lines.add(">[" + left + " more lines not shown]");
        }
        return lines;
    }

    /** Where to cut a line longer than {@link #WIDTH}: after the last space that leaves a part of it, else at it. */
    private static int wrapAt(String line) {
        int space = line.lastIndexOf(' ', WIDTH);
        return space > WIDTH / 2 ? space + 1 : WIDTH;
    }

    /**
     * A title, from tick1's own words: one line, cleaned and with tags broken as quoted text is, and with a
     * full stop after a last {@code (N)}, which VPL's editor would take for a grade and hide.
     */
    static String title(String words) {
        String line = breakTags(clean(words).replace('\n', ' ').strip());
        return "-" + (TITLE_GRADE.matcher(line).find() ? line + "." : line);
    }

    /**
     * {@code text} with its line breaks made {@code \n}, and every other control character (a lone
     * {@code \r}, C1 controls, the Unicode line and paragraph separators, and the marks that reorder text
     * on screen) removed; a tab becomes a space.
     */
    static String clean(String text) {
        String unix = text.replace("\r\n", "\n");
        StringBuilder kept = new StringBuilder(unix.length());
        for (int i = 0; i < unix.length(); i++) {
            char c = unix.charAt(i);
            if (c == '\n') {
                kept.append(c);
            } else if (c == '\t') {
                kept.append(' ');
            } else if (!invisible(c)) {
                kept.append(c);
            }
        }
        return kept.toString();
    }

    private static boolean invisible(char c) {
        return c < 0x20 || c >= 0x7F && c <= 0x9F || c == '\u2028' || c == '\u2029' || c == '\u200E' || c == '\u200F'
                || c >= '\u202A' && c <= '\u202E' || c >= '\u2066' && c <= '\u2069' || c == '\uFEFF';
    }

    /**
     * {@code line} with VPL's markers broken by a space: the block's tags ({@code <|--}, {@code --|>}) and
     * the {@code :=>>} of {@code Grade :=>>} and {@code Comment :=>>}.
     */
    static String breakTags(String line) {
        return line.replace("<|--", "<|- -").replace("--|>", "- -|>").replace(":=>>", ":=> >");
    }
}
