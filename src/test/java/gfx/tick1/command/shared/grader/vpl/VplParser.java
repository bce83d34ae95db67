package gfx.tick1.command.shared.grader.vpl;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * VPL's reading of an evaluation's output, written again here from the rules of its own source (our code,
 * not VPL's), so that tests see tick1's report as a student and Moodle see it:
 *
 * <ul>
 *   <li>{@code vpl_submission.class.php} of jcrodriguez-dis/moodle-mod_vpl (commit 871102ef0b2e, the 4.x
 *       line): {@code find_proposedgrade} takes the last match of {@code /^Grade :=>>(.*)$/m}, trimmed;
 *       {@code find_proposedcomment} takes {@code Comment :=>>} lines and blocks from a line that is only
 *       {@code <|--} to the next line that is only {@code --|>} (blanks and tabs allowed around the tag; with
 *       {@code \r?} before the line's end when the text holds a {@code \r\n}, whose blocks then have their
 *       {@code \r\n} made {@code \n}), an unclosed block running to the end;</li>
 *   <li>{@code amd/src/vplutil.js} of the same repository (commit 007ef4e4d7ab), {@code processResult}: lines
 *       split at {@code /\r\n|\n|\r/}; a line matching {@code /^-.* /} is a title, with a last
 *       {@code /\([-]?[\d]+[.]?[\d]*\)\s*$/} taken off as its grade; a line matching {@code /^\s*>/} is
 *       preformatted (the rest after the match); any other line is plain text; and in every line,
 *       {@code (^|.* |.*\/)FILE( on line | line |:|\()(\d+)(:|,)?(\d+)?(\))?} makes a link and an editor
 *       annotation on line {@code \3} of FILE.</li>
 * </ul>
 * PHP's PCRE treats only {@code \n} as a line end for {@code ^} and {@code $} (its default), so the Java
 * patterns here use {@link Pattern#UNIX_LINES}.
 */
public final class VplParser {

    private static final int M = Pattern.MULTILINE | Pattern.UNIX_LINES;
    private static final Pattern GRADE = Pattern.compile("^Grade :=>>(.*)$", M);
    private static final Pattern START = Pattern.compile("^[ \\t]*(Comment :=>>(.*)|<\\|--)[ \\t]*$", M);
    private static final Pattern END = Pattern.compile("^[ \\t]*--\\|>[ \\t]*$", M);
    private static final Pattern START_CRLF =
            Pattern.compile("^[ \\t]*(Comment :=>>([^\\r\\n]*)|<\\|--)[ \\t]*\\r?$", M);
    private static final Pattern END_CRLF = Pattern.compile("^[ \\t]*--\\|>[ \\t]*\\r?$", M);
    private static final Pattern TITLE_GRADE = Pattern.compile("\\([-]?[\\d]+[.]?[\\d]*\\)\\s*$");
    private static final Pattern CASE = Pattern.compile("^\\s*>", Pattern.UNICODE_CHARACTER_CLASS);

    private VplParser() {
    }

    /** What the jail's pseudo-terminal hands VPL for what a program printed: each {@code \n} as {@code \r\n}. */
    public static String throughPty(String printed) {
        return printed.replace("\n", "\r\n");
    }

    /** {@code find_proposedgrade}: the last grade line's value, trimmed as PHP's trim does; "" for none. */
    public static String proposedGrade(String text) {
        Matcher grade = GRADE.matcher(text);
        String found = "";
        while (grade.find()) {
            found = grade.group(1).replaceAll("^[ \\t\\n\\r\\x00\\x0B]+|[ \\t\\n\\r\\x00\\x0B]+$", "");
        }
        return found;
    }

    /** How many lines {@code find_proposedgrade} sees as grade lines. */
    public static int gradeLines(String text) {
        return (int) GRADE.matcher(text).results().count();
    }

    /** {@code find_proposedcomment}: the comments' text, joined as VPL joins them. */
    public static String proposedComment(String text) {
        boolean crlf = text.contains("\r\n");
        Pattern start = crlf ? START_CRLF : START, end = crlf ? END_CRLF : END;
        StringBuilder comments = new StringBuilder();
        int offset = 0;
        while (offset <= text.length()) {
            Matcher found = start.matcher(text);
            if (!found.find(offset)) {
                break;
            }
            if ("<|--".equals(found.group(1))) {
                int blockStart = Math.min(text.length(), found.end() + 1);
                Matcher closing = end.matcher(text);
                if (!closing.find(blockStart)) {
                    comments.append(text.substring(blockStart));
                    break;
                }
                String block = text.substring(blockStart, closing.start());
                comments.append(crlf ? block.replace("\r\n", "\n") : block);
                offset = closing.end() + 1;
            } else {
                comments.append(found.group(2)).append('\n');
                offset = found.end() + 1;
            }
        }
        return comments.toString();
    }

    /** A line of the comments as the editor shows it. */
    public record Line(Kind kind, String text) {
    }

    public enum Kind { TITLE, PREFORMATTED, TEXT }

    /** {@code processResult}: each line of the comments, as a title, preformatted or plain text. */
    public static List<Line> lines(String comments) {
        if (comments.replaceAll("(?m)^\\s+$", "").isEmpty()) {
            return List.of();
        }
        List<Line> lines = new ArrayList<>();
        for (String line : comments.split("\\r\\n|\\n|\\r", -1)) {
            Matcher preformatted = CASE.matcher(line);
            if (line.startsWith("-")) {
                String title = line.substring(1);
                Matcher grade = TITLE_GRADE.matcher(title);
                lines.add(new Line(Kind.TITLE, grade.find() ? title.substring(0, grade.start()) : title));
            } else if (preformatted.find()) {
                lines.add(new Line(Kind.PREFORMATTED, line.substring(preformatted.end())));
            } else {
                lines.add(new Line(Kind.TEXT, line));
            }
        }
        return lines;
    }

    /** The titles the editor shows. */
    public static List<String> titles(String comments) {
        return lines(comments).stream().filter(line -> line.kind() == Kind.TITLE).map(Line::text).toList();
    }

    /** An editor annotation: the file and the line (1-based) it marks. */
    public record Annotation(String file, int line) {
    }

    /**
     * The annotations {@code processResult} makes for the submitted {@code files}, from each line's text as
     * shown (a preformatted line's after its {@code >}).
     */
    public static List<Annotation> annotations(String comments, List<String> files) {
        List<Annotation> annotations = new ArrayList<>();
        for (Line shown : lines(comments)) {
            String line = shown.text();
            for (String file : files) {
                Matcher link = Pattern.compile("(^|.* |.*/)" + Pattern.quote(file)
                        + "( on line | line |:|\\()(\\d+)(:|,)?(\\d+)?(\\))?").matcher(line);
                if (link.find()) {
                    annotations.add(new Annotation(file, Integer.parseInt(link.group(3))));
                }
            }
        }
        return annotations;
    }
}
