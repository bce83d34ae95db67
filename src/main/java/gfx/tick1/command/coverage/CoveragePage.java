package gfx.tick1.command.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.coverage.Caught;
import gfx.tick1.command.shared.coverage.Coverage;
import java.util.List;

/** A {@link Coverage} as one HTML page: the table, what each scene alone catches, what none does, and the pairs. */
final class CoveragePage {

    private CoveragePage() {
    }

    static String of(Coverage coverage) {
        StringBuilder page = new StringBuilder("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                + "<title>tick1 coverage</title>\n<style>body{font-family:sans-serif}td,th{padding:2px 8px}"
                + "td.n{text-align:right}td.zero{color:#a00}</style>\n</head>\n<body>\n"
                + "<h1>Which mistakes the scenes catch"
                + "</h1>\n<p>Pixels differing from the image a pass needs, at " + coverage.width() + " x "
                + coverage.height() + "; 0: the scene does not catch the mistake.</p>\n");
        table(page, coverage, coverage.mistakes(), true);
        page.append("<h2>Caught by one scene alone</h2>\n<ul>\n");
        for (int i = 0; i < coverage.scenes().size(); i++) {
            List<Variant> only = coverage.caughtOnlyBy(i);
            page.append("<li><bdi>").append(escape(coverage.scenes().get(i))).append("</bdi>: ")
                    .append(only.isEmpty() ? "none" : escape(String.join("; ", only.stream().map(Variant::title)
                            .toList()))).append("</li>\n");
        }
        page.append("</ul>\n<h2>Caught by no scene</h2>\n<ul>\n");
        for (Variant mistake : coverage.missed()) {
            page.append("<li>").append(escape(mistake.title()))
                    .append(coverage.reason(mistake).map(reason -> ": " + escape(reason.words())).orElse(""))
                    .append("</li>\n");
        }
        page.append(coverage.missed().isEmpty() ? "<li>none</li>\n" : "").append("</ul>\n");
        if (!coverage.pairs().isEmpty()) {
            page.append("<h2>Pairs tick1 names together, where some scene catches neither mistake alone</h2>\n");
            table(page, coverage, coverage.pairs(), false);
        }
        return page.append("</body>\n</html>\n").toString();
    }

    private static void table(StringBuilder page, Coverage coverage, List<Caught> rows, boolean total) {
        page.append("<table>\n<tr><th>mistake</th>");
        coverage.scenes().forEach(scene -> page.append("<th><bdi>").append(escape(scene)).append("</bdi></th>"));
        page.append(total ? "<th>all</th>" : "").append("</tr>\n");
        for (Caught row : rows) {
            page.append("<tr><td>").append(escape(row.title())).append("</td>");
            row.pixels().forEach(pixels -> cell(page, pixels));
            if (total) {
                cell(page, row.total());
            }
            page.append("</tr>\n");
        }
        page.append("</table>\n");
    }

    private static void cell(StringBuilder page, long pixels) {
        page.append("<td class=\"").append(pixels == 0 ? "n zero" : "n").append("\">")
                .append(CoverageTable.number(pixels)).append("</td>");
    }

    /**
     * Text for an element's content or a quoted attribute: the five characters that can end either
     * as references, and control characters (which a page may not hold) as U+FFFD.
     */
    static String escape(String text) {
        return text.replaceAll("\\p{Cc}", "\uFFFD").replace("&", "&amp;").replace("<", "&lt;")
                .replace(">", "&gt;").replace("\"", "&quot;").replace("'", "&#39;");
    }
}
