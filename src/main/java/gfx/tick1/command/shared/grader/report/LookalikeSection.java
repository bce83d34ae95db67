package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.lookalike.Lookalike;
import gfx.tick1.command.shared.grader.lookalike.Lookalikes;
import gfx.tick1.engine.io.OwnFolder;
import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The look-alikes in the report: {@code lookalikes.csv}, the "Look alike" section of the index
 * with the top pairs, and a side-by-side page for each pair the section shows.
 */
final class LookalikeSection {

    /** The most pairs the section shows for their tokens, and the most it adds for their wrong answers. */
    static final int MOST_SHOWN = 25;

    private LookalikeSection() {
    }

    /** The pairs the section shows, in order: the most similar, then the same wrong answers not among them. */
    static List<Lookalike> shown(List<Lookalike> pairs) {
        List<Lookalike> shown = new ArrayList<>(pairs.subList(0, Math.min(MOST_SHOWN, pairs.size())));
        pairs.stream().skip(shown.size()).filter(pair -> pair.reason() == Lookalike.Reason.SAME_UNCATALOGUED_ANSWERS
                || pair.reason() == Lookalike.Reason.SAME_WRONG_ANSWERS).limit(MOST_SHOWN).forEach(shown::add);
        return shown;
    }

    /**
     * Writes lookalikes.csv and the pages of the pairs shown (deleting the pages of an earlier run that
     * are not written again), and returns the section for the index.
     */
    static String write(Path reportFolder, List<Lookalike> pairs) throws IOException {
        ReportFiles.write(reportFolder.resolve(LookalikesCsv.NAME), LookalikesCsv.csv(pairs));
        List<Lookalike> shown = shown(pairs);
        // A link there is replaced, never written or deleted through.
        Path folder = OwnFolder.at(reportFolder.resolve(LookalikePage.FOLDER));
        List<String> written = new ArrayList<>();
        for (int i = 0; i < shown.size(); i++) {
            String name = LookalikePage.fileName(i + 1);
            ReportFiles.write(folder.resolve(name), LookalikePage.html(shown.get(i)));
            written.add(name);
        }
        removeOtherPages(folder, written);
        return section(shown, pairs.size());
    }

    private static void removeOtherPages(Path folder, List<String> written) throws IOException {
        try (DirectoryStream<Path> pages = Files.newDirectoryStream(folder, "pair-*.html")) {
            for (Path page : pages) {
                if (!written.contains(page.getFileName().toString())) {
                    Files.deleteIfExists(page);
                }
            }
        }
    }

    static String section(List<Lookalike> shown, int listed) {
        StringBuilder out = new StringBuilder(1024 + 400 * shown.size());
        out.append("<h2 id=\"look-alike\">Look alike</h2>\n");
        if (shown.isEmpty()) {
            return out.append("<p class=\"hint\">No two submissions look alike, and none looks like tick1's "
                    + "reference.</p>\n").toString();
        }
        out.append("<p class=\"hint\">Pairs whose two methods share most of their tokens after renaming (the starter "
                + "code set aside), submissions like tick1's reference, and failed pairs with the same rare wrong "
                + "answers. Correct code converges: a look-alike is a reason to talk with the students, not a "
                + "verdict. A pair opens its side-by-side page. All ").append(listed).append(" are in <a href=\"")
                .append(Html.relativeUrl(LookalikesCsv.NAME)).append("\">").append(LookalikesCsv.NAME)
                .append("</a>.</p>\n<table id=\"lookalikes\">\n<thead><tr><th scope=\"col\">A</th>"
                        + "<th scope=\"col\">B</th><th scope=\"col\">Similarity</th><th scope=\"col\">Why</th>"
                        + "</tr></thead>\n<tbody>\n");
        for (int i = 0; i < shown.size(); i++) {
            Lookalike pair = shown.get(i);
            String page = Html.relativeUrl(LookalikePage.FOLDER, LookalikePage.fileName(i + 1));
            out.append("<tr><td><a href=\"").append(page).append("\"><bdi>")
                    .append(Html.escape(pair.a().fullName())).append("</bdi></a></td><td><a href=\"").append(page)
                    .append("\"><bdi>").append(Html.escape(pair.b() == null ? Lookalikes.REFERENCE
                            : pair.b().fullName())).append("</bdi></a></td><td>")
                    .append(Lookalikes.percent(pair.similarity())).append("</td><td>")
                    .append(Html.escape(pair.why())).append("</td></tr>\n");
        }
        return out.append("</tbody>\n</table>\n").toString();
    }
}
