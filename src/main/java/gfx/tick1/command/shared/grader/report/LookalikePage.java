package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.lookalike.ComparedCode;
import gfx.tick1.command.shared.grader.lookalike.Lookalike;
import gfx.tick1.command.shared.grader.lookalike.Lookalikes;
import gfx.tick1.command.shared.grader.model.Submission;
import java.util.List;

/**
 * The side-by-side page of one pair of look-alikes: each side's methods as they were compared,
 * the runs the two share marked, the starter code's tokens greyed. Everything of a student's is
 * escaped (their code is hostile HTML), and each side shows at most {@link #MOST_CHARACTERS}
 * characters, whatever the file held.
 */
final class LookalikePage {

    /** The report folder's sub-folder of these pages. */
    static final String FOLDER = "lookalikes";
    /** The most characters of one side's code shown: many times a real solution's. */
    static final int MOST_CHARACTERS = 60_000;

    private static final String STYLE = Html.resource("report.css") + """
            .sides { display: grid; grid-template-columns: 1fr 1fr; gap: 1em; }
            pre.code { background: #f6f6f6; padding: 0.6em; font-size: 13px; overflow-x: auto; white-space: pre; }
            mark { background: #ffe08a; }
            .base { color: #999; }
            """;

    private LookalikePage() {
    }

    /** The page's file name for the pair at {@code rank} (1 for the first listed). */
    static String fileName(int rank) {
        return "pair-" + rank + ".html";
    }

    static String html(Lookalike pair) {
        String title = "Look alike: " + LookalikesCsv.identifier(pair.a()) + " and "
                + (pair.b() == null ? Lookalikes.REFERENCE : LookalikesCsv.identifier(pair.b()));
        // A pair listed for its tokens says its share in its reason already.
        boolean byTokens = pair.reason() == Lookalike.Reason.TOKENS || pair.reason() == Lookalike.Reason.REFERENCE;
        StringBuilder out = new StringBuilder(16_384);
        out.append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n")
                .append("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n")
                .append("<title>").append(Html.escape(title)).append("</title>\n<style>\n").append(STYLE)
                .append("</style>\n</head>\n<body>\n<h1>").append(Html.escape(title)).append("</h1>\n")
                .append("<p class=\"summary\">").append(Html.escape(pair.why()))
                .append(byTokens ? "" : "; " + Lookalikes.percent(pair.similarity()) + " of the tokens in shared runs")
                .append(".</p>\n")
                .append("<p class=\"hint\">A look-alike is a reason to talk with the students, not a verdict: correct "
                        + "code for two short methods converges. Shown: each side's intersectionWith, illuminate and "
                        + "any member it added, as compared: one statement a line, comments dropped, redundant "
                        + "parentheses made canonical, locals and parameters named #1, #2, ... in the order they are "
                        + "declared. <mark>Marked</mark>: runs of at least ").append(Lookalikes.MINIMUM_MATCH)
                .append(" tokens the two share. <span class=\"base\">Grey</span>: the starter code every student "
                        + "was given, which does not count.</p>\n<div class=\"sides\">\n");
        side(out, pair.a(), pair.compared().codeA(), pair.compared().sharedOfA());
        side(out, pair.b(), pair.compared().codeB(), pair.compared().sharedOfB());
        return out.append("</div>\n</body>\n</html>\n").toString();
    }

    private static void side(StringBuilder out, Submission student, ComparedCode code, boolean[] shared) {
        out.append("<section>\n<h2>");
        if (student == null) {
            out.append(Html.escape(Lookalikes.REFERENCE));
        } else {
            out.append("<a href=\"../").append(Html.relativeUrl(ReportFiles.FEEDBACK, student.folder(),
                    FeedbackPage.HTML)).append("\"><bdi>").append(Html.escape(student.fullName()))
                    .append("</bdi></a> (").append(Html.escape(LookalikesCsv.identifier(student))).append(")");
        }
        out.append("</h2>\n");
        code.notes().forEach(note -> out.append("<p class=\"hint\">").append(Html.escape(note)).append("</p>\n"));
        List<List<ComparedCode.Span>> spans = code.spans(shared);
        int left = MOST_CHARACTERS;
        for (int m = 0; m < code.members().size() && left > 0; m++) {
            ComparedCode.Member member = code.members().get(m);
            String text = member.text().length() > left ? member.text().substring(0, left) : member.text();
            left -= text.length();
            out.append("<h3>").append(Html.escape(member.file())).append(": ")
                    .append(Html.escape(member.signature())).append("</h3>\n<pre class=\"code\">");
            marked(out, text, spans.get(m));
            out.append(text.length() < member.text().length() ? "\n\u2026 (cut)" : "").append("</pre>\n");
        }
        out.append("</section>\n");
    }

    /** {@code text}, escaped, with each span in its mark; spans past the text's end are cut there. */
    private static void marked(StringBuilder out, String text, List<ComparedCode.Span> spans) {
        int at = 0;
        for (ComparedCode.Span span : spans) {
            if (span.start() >= text.length()) {
                break;
            }
            int end = Math.min(span.end(), text.length());
            out.append(Html.escape(text.substring(at, span.start())))
                    .append(span.kind() == ComparedCode.Kind.SHARED ? "<mark>" : "<span class=\"base\">")
                    .append(Html.escape(text.substring(span.start(), end)))
                    .append(span.kind() == ComparedCode.Kind.SHARED ? "</mark>" : "</span>");
            at = end;
        }
        out.append(Html.escape(text.substring(at)));
    }
}
