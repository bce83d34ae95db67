package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.StudentResult;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The report's bar chart of failures by diagnosis: which mistakes are common in this cohort. One
 * horizontal bar per label, most common first (equal counts in the labels' order), drawn as inline
 * SVG by the program, so the page shows it without a script or anything from outside.
 */
final class DiagnosisChart {

    private static final int LABEL_WIDTH = 300;
    private static final int BAR_SPACE = 380;
    private static final int ROW = 26;
    private static final int BAR = 18;
    private static final int LONGEST_LABEL = 44;

    private DiagnosisChart() {
    }

    /** A result's diagnosis, or words saying it has none. */
    static String label(StudentResult result) {
        return result.diagnosis() == null ? "no diagnosis" : result.diagnosis().label();
    }

    /** How many failed submissions carry each diagnosis, most common first. */
    static Map<String, Integer> failuresByDiagnosis(List<StudentResult> results) {
        Map<String, Integer> counts = new TreeMap<>();
        results.stream().filter(result -> Standing.of(result) == Standing.FAILED)
                .forEach(result -> counts.merge(label(result), 1, Integer::sum));
        Map<String, Integer> ordered = new LinkedHashMap<>();
        counts.entrySet().stream()
                .sorted(Map.Entry.<String, Integer>comparingByValue(Comparator.reverseOrder()))
                .forEach(entry -> ordered.put(entry.getKey(), entry.getValue()));
        return ordered;
    }

    static String svg(List<StudentResult> results) {
        Map<String, Integer> counts = failuresByDiagnosis(results);
        if (counts.isEmpty()) {
            return "<p class=\"no-failures\">No submission failed.</p>\n";
        }
        int most = counts.values().iterator().next();
        int height = counts.size() * ROW + 4;
        StringBuilder out = new StringBuilder(512 + 400 * counts.size());
        out.append("<svg id=\"diagnoses\" role=\"img\" width=\"")
                .append(LABEL_WIDTH + BAR_SPACE + 60).append("\" height=\"").append(height)
                .append("\" aria-label=\"failures by diagnosis\">\n");
        int y = 2;
        for (Map.Entry<String, Integer> entry : counts.entrySet()) {
            String label = entry.getKey();
            int count = entry.getValue();
            int length = Math.max(2, Math.round((float) BAR_SPACE * count / most));
            String shown = label.length() > LONGEST_LABEL ? label.substring(0, LONGEST_LABEL - 1) + "\u2026" : label;
            out.append("<g class=\"bar\" data-label=\"").append(Html.escape(label)).append("\" data-count=\"")
                    .append(count).append("\"><title>").append(Html.escape(label)).append(": ").append(count)
                    .append("</title>\n<text class=\"label\" x=\"").append(LABEL_WIDTH - 8).append("\" y=\"")
                    .append(y + BAR - 5).append("\" text-anchor=\"end\">").append(Html.escape(shown))
                    .append("</text>\n<rect x=\"").append(LABEL_WIDTH).append("\" y=\"").append(y)
                    .append("\" width=\"").append(length).append("\" height=\"").append(BAR).append("\"/>\n")
                    .append("<text class=\"count\" x=\"").append(LABEL_WIDTH + length + 6).append("\" y=\"")
                    .append(y + BAR - 5).append("\">").append(count).append("</text></g>\n");
            y += ROW;
        }
        return out.append("</svg>\n").toString();
    }
}
