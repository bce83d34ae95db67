package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The index's "The year at a glance": how many students made each catalogued mistake, each tested
 * finding of the probes and each note on what the course's scenes do not test (the notes in a table
 * of their own), each counted under Failed or Passed by that student's result; the handout
 * sections the feedback sent students to reread, the grades, and the time each submission took to
 * grade in the sandbox.
 */
final class YearAtAGlance {

    /** The most rows of one table: the commonest; a cohort's long tail is in the students' table. */
    static final int MOST_ROWS = 30;
    /** The limits of the bands of grading time, in seconds. */
    private static final long[] TIME_BANDS = {1, 5, 15, 60};

    private YearAtAGlance() {
    }

    /** Students counted under one heading: those who failed and those who passed. */
    private static final class Count {
        int failed;
        int passed;
    }

    static String html(List<StudentResult> results, List<String> grades) {
        Map<String, Count> mistakes = new TreeMap<>();
        Map<String, Count> findings = new TreeMap<>();
        Map<String, Count> untested = new TreeMap<>();
        Map<String, Count> sections = new TreeMap<>();
        for (StudentResult result : results) {
            Findings found = result.findings();
            if (found.catalogued() != null) {
                add(mistakes, found.catalogued().title(), result.passed());
            }
            found.failed().forEach(fact -> add(findings, fact, result.passed()));
            found.notes().forEach(note -> add(untested, note, result.passed()));
            FeedbackPage.rereading(result).forEach(section -> add(sections, section, result.passed()));
        }
        StringBuilder out = new StringBuilder(4096);
        out.append("<h2 id=\"year\">The year at a glance</h2>\n");
        table(out, "Catalogued mistakes: a wrong image one catalogue entry reproduces exactly", "Mistake", mistakes);
        table(out, "What the probes found: facts of students' intersectionWith and illuminate on tick1's inputs",
                "Finding", findings);
        table(out, "Notes on what the course's scenes do not test: never a reason to fail", "Note", untested);
        table(out, "The handout sections the feedback sent students to reread", "Section", sections);
        grades(out, grades);
        times(out, results);
        return out.toString();
    }

    private static void add(Map<String, Count> counts, String key, boolean passed) {
        Count count = counts.computeIfAbsent(key, k -> new Count());
        if (passed) {
            count.passed++;
        } else {
            count.failed++;
        }
    }

    /** A table of counts, the most students first, at most {@link #MOST_ROWS} rows. */
    private static void table(StringBuilder out, String caption, String heading, Map<String, Count> counts) {
        out.append("<h3>").append(Html.escape(caption)).append("</h3>\n");
        if (counts.isEmpty()) {
            out.append("<p class=\"hint\">None.</p>\n");
            return;
        }
        out.append("<table class=\"glance\">\n<thead><tr><th scope=\"col\">").append(heading)
                .append("</th><th scope=\"col\">Failed</th><th scope=\"col\">Passed</th></tr></thead>\n<tbody>\n");
        counts.entrySet().stream()
                .sorted(Comparator.comparingInt((Map.Entry<String, Count> e) -> e.getValue().failed
                        + e.getValue().passed).reversed())
                .limit(MOST_ROWS)
                .forEach(e -> out.append("<tr><td>").append(Html.escape(CellText.bounded(e.getKey(),
                        CellText.MAX_CELL))).append("</td><td>").append(e.getValue().failed).append("</td><td>")
                        .append(e.getValue().passed).append("</td></tr>\n"));
        out.append("</tbody>\n</table>\n");
        if (counts.size() > MOST_ROWS) {
            out.append("<p class=\"hint\">And ").append(counts.size() - MOST_ROWS).append(" more.</p>\n");
        }
    }

    /** How many students got each grade, highest first; a blank grade (files never run) as "none". */
    private static void grades(StringBuilder out, List<String> grades) {
        Map<String, Integer> counts = new TreeMap<>(Comparator.<String, Double>comparing(
                grade -> grade.isEmpty() ? Double.NEGATIVE_INFINITY : Double.parseDouble(grade)).reversed());
        grades.forEach(grade -> counts.merge(grade == null ? "" : grade, 1, Integer::sum));
        out.append("<h3>Grades</h3>\n<table class=\"glance\" id=\"grades\">\n<thead><tr><th scope=\"col\">Grade"
                + "</th><th scope=\"col\">Students</th></tr></thead>\n<tbody>\n");
        counts.forEach((grade, count) -> out.append("<tr><td>").append(grade.isEmpty() ? "none (not run)"
                : Html.escape(grade)).append("</td><td>").append(count).append("</td></tr>\n"));
        out.append("</tbody>\n</table>\n");
    }

    /** How many submissions took how long to grade in the sandbox, in bands, with the median and the longest. */
    private static void times(StringBuilder out, List<StudentResult> results) {
        out.append("<h3>Time in the sandbox</h3>\n");
        if (results.isEmpty()) {
            out.append("<p class=\"hint\">None.</p>\n");
            return;
        }
        List<Duration> times = new ArrayList<>(results.stream().map(StudentResult::time).sorted().toList());
        Map<String, Integer> bands = new LinkedHashMap<>();
        for (int i = 0; i <= TIME_BANDS.length; i++) {
            bands.put(i == 0 ? "under " + TIME_BANDS[0] + " s" : i == TIME_BANDS.length ? TIME_BANDS[i - 1]
                    + " s or more" : TIME_BANDS[i - 1] + " to " + TIME_BANDS[i] + " s", 0);
        }
        List<String> names = new ArrayList<>(bands.keySet());
        for (Duration time : times) {
            int band = 0;
            while (band < TIME_BANDS.length && time.toMillis() >= TIME_BANDS[band] * 1000) {
                band++;
            }
            bands.merge(names.get(band), 1, Integer::sum);
        }
        out.append("<p>Median ").append(CohortPage.duration(times.get(times.size() / 2))).append(", longest ")
                .append(CohortPage.duration(times.get(times.size() - 1)))
                .append(" (each student's is in the table below).</p>\n<table class=\"glance\" id=\"times\">\n")
                .append("<thead><tr><th scope=\"col\">Time</th><th scope=\"col\">Students</th></tr></thead>\n")
                .append("<tbody>\n");
        bands.forEach((band, count) -> out.append("<tr><td>").append(band).append("</td><td>").append(count)
                .append("</td></tr>\n"));
        out.append("</tbody>\n</table>\n");
    }
}
