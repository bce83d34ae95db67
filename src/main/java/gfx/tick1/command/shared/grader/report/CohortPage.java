package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * {@code index.html}, the cohort at a glance: how many passed, the chart of failures by diagnosis,
 * and a table of every student that sorts by any column. One file, opened from disk: its style
 * sheet and script are written into it, and it links only to the feedback folders beside it.
 * Thumbnails load lazily, so a cohort of hundreds opens at once.
 */
final class CohortPage {

    /** A table column: its heading, and whether it sorts as numbers (else as text, digits by value). */
    private record Column(String heading, boolean numeric) {
    }

    private static final List<Column> COLUMNS = List.of(new Column("Name", false), new Column("Id", false),
            new Column("Result", false), new Column("Scenes", true), new Column("Grade", true),
            new Column("Diagnosis", false), new Column("Reason", false), new Column("Time", true),
            new Column("Difference maps", true));

    private CohortPage() {
    }

    /** The page's style sheet and script, written into it. */
    private static final String STYLE = Html.resource("report.css");
    private static final String SCRIPT = Html.resource("cohort.js");

    /**
     * The page for {@code results}; {@code grades} holds each one's mark as the gradebook has it.
     * {@code beside} are files of the report folder to link to under the summary (the feedback zip,
     * the gradebook), by their names.
     */
    static String html(List<StudentResult> results, List<String> grades, List<String> beside) {
        return html(results, grades, beside, "");
    }

    /** As {@link #html(List, List, List)}, with {@code sections} (HTML: the year at a glance, ...) after the chart. */
    static String html(List<StudentResult> results, List<String> grades, List<String> beside, String sections) {
        long passed = results.stream().filter(result -> Standing.of(result) == Standing.PASSED).count();
        long notGraded = results.stream().filter(result -> Standing.of(result) == Standing.NOT_GRADED).count();
        StringBuilder out = new StringBuilder(4096 + 1024 * results.size());
        out.append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n")
                .append("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n")
                .append("<title>Tick 1: the cohort at a glance</title>\n<style>\n").append(STYLE)
                .append("</style>\n</head>\n<body data-status=\"loading\">\n<h1>Tick 1: the cohort at a glance</h1>\n")
                .append("<p class=\"summary\"><strong id=\"passed-count\">").append(passed)
                .append("</strong> of <strong id=\"total-count\">").append(results.size())
                .append("</strong> passed; <strong id=\"failed-count\">").append(results.size() - passed - notGraded)
                .append("</strong> failed; <strong id=\"not-graded-count\">").append(notGraded)
                .append("</strong> not graded.</p>\n");
        if (!beside.isEmpty()) {
            out.append("<p class=\"files\">Files:");
            beside.forEach(file -> out.append(" <a href=\"").append(Html.relativeUrl(file)).append("\">")
                    .append(Html.escape(file)).append("</a>"));
            out.append("</p>\n");
        }
        out.append("<h2>Failures by diagnosis</h2>\n")
                .append(DiagnosisChart.svg(results))
                .append(sections)
                .append("<h2>Students</h2>\n<p class=\"hint\">Click a column's heading to sort by it; click again "
                        + "to reverse. A name opens the student's feedback.</p>\n")
                .append("<table id=\"students\">\n<thead><tr>");
        for (Column column : COLUMNS) {
            out.append("<th").append(column.numeric() ? " data-type=\"number\"" : "").append(" scope=\"col\">")
                    .append("<button type=\"button\">").append(column.heading()).append("</button></th>");
        }
        out.append("</tr></thead>\n<tbody>\n");
        for (int i = 0; i < results.size(); i++) {
            row(out, results.get(i), Objects.requireNonNullElse(grades.get(i), ""));
        }
        return out.append("</tbody>\n</table>\n<script>\n").append(SCRIPT)
                .append("</script>\n</body>\n</html>\n").toString();
    }

    private static void row(StringBuilder out, StudentResult result, String grade) {
        Submission student = result.submission();
        ReasonText why = ReasonText.of(result.reason());
        String feedback = Html.relativeUrl(ReportFiles.FEEDBACK, student.folder(), FeedbackPage.HTML);
        Standing standing = Standing.of(result);
        out.append("<tr class=\"").append(standing.style()).append("\">")
                .append("<td><a href=\"").append(feedback).append("\"><bdi>").append(Html.escape(student.fullName()))
                .append("</bdi></a></td>")
                .append("<td><bdi>").append(Html.escape(student.id())).append("</bdi></td>")
                .append("<td class=\"result\">").append(standing.words()).append("</td>")
                .append("<td data-sort=\"").append(share(result)).append("\">").append(result.scenesTotal() == 0
                        ? "none run" : result.scenesPassed() + " of " + result.scenesTotal()).append("</td>")
                .append("<td data-sort=\"").append(Html.escape(grade)).append("\">").append(Html.escape(grade))
                .append("</td>")
                .append("<td>").append(Html.escape(DiagnosisChart.label(result))).append("</td>")
                .append("<td class=\"reason\" title=\"").append(Html.escape(why.prose()))
                .append("\">").append(Html.escape(CellText.shortReason(why.prose()))).append(why.quotedHtml())
                .append("</td>")
                .append("<td class=\"time\" data-sort=\"").append(result.time().toMillis()).append("\">")
                .append(duration(result.time())).append("</td>");
        List<String> titles = FeedbackPage.sceneTitles(result.scenes());
        StringBuilder thumbnails = new StringBuilder();
        int maps = 0;
        for (int i = 0; i < result.scenes().size(); i++) {
            SceneResult scene = result.scenes().get(i);
            if (!scene.hidden() && scene.files().heatMap() != null) {
                maps++;
                thumbnails.append("<a href=\"").append(feedback).append("\"><img class=\"thumbnail\" src=\"")
                        .append(Html.relativeUrl(ReportFiles.FEEDBACK, student.folder(), scene.files().heatMap()))
                        .append("\" loading=\"lazy\" decoding=\"async\" width=\"160\" height=\"120\" ")
                        .append("alt=\"heat map of ")
                        .append(Html.escape(titles.get(i))).append("\"></a>");
            }
        }
        out.append("<td data-sort=\"").append(maps).append("\">").append(thumbnails).append("</td></tr>\n");
    }

    /** The share of scenes passed, for sorting; a submission that ran nothing sorts below any that ran. */
    private static String share(StudentResult result) {
        return result.scenesTotal() == 0 ? "-1"
                : String.format(Locale.ROOT, "%.6f", (double) result.scenesPassed() / result.scenesTotal());
    }

    /** "850 ms", "3.2 s", "2 min 05 s": what a person reads at a glance; the cell sorts by milliseconds. */
    static String duration(Duration time) {
        long millis = time.toMillis();
        if (millis < 1000) {
            return millis + " ms";
        }
        if (millis < 60_000) {
            return String.format(Locale.ROOT, "%.1f s", millis / 1000.0);
        }
        long seconds = Math.round(millis / 1000.0);
        return String.format(Locale.ROOT, "%d min %02d s", seconds / 60, seconds % 60);
    }
}
