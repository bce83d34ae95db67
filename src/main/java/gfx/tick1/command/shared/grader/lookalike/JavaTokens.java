package gfx.tick1.command.shared.grader.lookalike;

import java.util.ArrayList;
import java.util.List;

/**
 * The tokens of a member's canonical text ({@code JavaMembers.Member#key}: JavaParser's printing of
 * the member with comments dropped, parentheses made canonical and locals named {@code #1},
 * {@code #2}, ...): identifiers, keywords, literals, operators and separators, each as the span of
 * the text it covers. White space is not a token, and the text holds no comment.
 */
final class JavaTokens {

    /** The operators of more than one character, longest first, so that the longest always matches. */
    private static final List<String> OPERATORS = List.of(">>>=", "<<=", ">>=", ">>>", "...", "->", "::", "++",
            "--", "&&", "||", "==", "!=", "<=", ">=", "+=", "-=", "*=", "/=", "&=", "|=", "^=", "%=", "<<", ">>");

    private JavaTokens() {
    }

    /** Each token's span in {@code text}, in order: start, end (exclusive), start, end, ... */
    static int[] spans(String text) {
        List<Integer> spans = new ArrayList<>();
        int i = 0;
        int n = text.length();
        while (i < n) {
            char c = text.charAt(i);
            int end;
            if (Character.isWhitespace(c)) {
                i++;
                continue;
            } else if (text.startsWith("//", i)) {
                end = lineEnd(text, i);
                i = end;
                continue;
            } else if (text.startsWith("/*", i)) {
                int close = text.indexOf("*/", i + 2);
                i = close < 0 ? n : close + 2;
                continue;
            } else if (c == '#' || Character.isJavaIdentifierStart(c)) {
                end = i + 1;
                while (end < n && Character.isJavaIdentifierPart(text.charAt(end))) {
                    end++;
                }
            } else if (Character.isDigit(c) || c == '.' && i + 1 < n && Character.isDigit(text.charAt(i + 1))) {
                end = number(text, i);
            } else if (c == '"' || c == '\'') {
                end = quoted(text, i);
            } else {
                end = i + operator(text, i).length();
            }
            spans.add(i);
            spans.add(end);
            i = end;
        }
        return spans.stream().mapToInt(Integer::intValue).toArray();
    }

    private static int lineEnd(String text, int from) {
        int end = text.indexOf('\n', from);
        return end < 0 ? text.length() : end;
    }

    /** A number literal: digits, letters, points and underscores, and a sign right after an exponent's e (p in hex). */
    private static int number(String text, int start) {
        boolean hex = text.startsWith("0x", start) || text.startsWith("0X", start);
        int end = start + 1;
        while (end < text.length()) {
            char c = text.charAt(end);
            boolean sign = (c == '+' || c == '-') && (hex ? "pP" : "eE").indexOf(text.charAt(end - 1)) >= 0;
            if (!(Character.isLetterOrDigit(c) || c == '.' || c == '_' || sign)) {
                break;
            }
            end++;
        }
        return end;
    }

    /** A string, character or text-block literal, to its closing quote (or the end of the text). */
    private static int quoted(String text, int start) {
        String close = text.startsWith("\"\"\"", start) ? "\"\"\"" : String.valueOf(text.charAt(start));
        int i = start + close.length();
        while (i < text.length()) {
            if (text.charAt(i) == '\\') {
                i += 2;
            } else if (text.startsWith(close, i)) {
                return i + close.length();
            } else {
                i++;
            }
        }
        return text.length();
    }

    private static String operator(String text, int at) {
        for (String operator : OPERATORS) {
            if (text.startsWith(operator, at)) {
                return operator;
            }
        }
        return text.substring(at, at + 1);
    }
}
