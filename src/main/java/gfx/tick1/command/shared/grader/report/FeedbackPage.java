package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * One student's feedback, ready to return: the result, the reason, what to reread, and each
 * scene's verdict with its explanation and, for a scene that is not hidden, its three images
 * (heat map, yours, expected), which lie beside the page. As HTML ({@code feedback.html}, a page
 * that needs nothing but the files beside it) and as plain text ({@code feedback.txt}, for
 * whatever cannot show a page: Moodle's file list on a phone, an e-mail, a terminal).
 *
 * <p>A hidden scene is called "hidden scene N" and shows only its verdict and explanation: its
 * name may tell what it holds, and an image would draw it.
 */
final class FeedbackPage {

    static final String HTML = "feedback.html";
    static final String TEXT = "feedback.txt";

    /** How a row's reason sends its reader to the feedback (grade's own words). */
    private static final String SEE_THE_FEEDBACK = " (see the feedback)";

    /** The most sections a feedback page asks to reread. */
    static final int MOST_TO_REREAD = 3;

    private static final String STYLE = Html.resource("report.css");

    private FeedbackPage() {
    }

    /** What a scene is called in feedback: its name, or "hidden scene N" counting the hidden ones. */
    static List<String> sceneTitles(List<SceneResult> scenes) {
        List<String> titles = new ArrayList<>();
        int hidden = 0;
        for (SceneResult scene : scenes) {
            titles.add(scene.hidden() ? "hidden scene " + ++hidden : scene.name());
        }
        return titles;
    }

    /** The images of a scene that a student may see, as file names in the feedback folder. */
    static List<String> images(SceneResult scene) {
        return scene.hidden() ? List.of() : scene.files().named();
    }

    /**
     * "passed", or "not passed: 1 of 2 scenes matched" (or the like when nothing could run), or "not
     * graded" when tick1 could not grade it: no verdict on the code (the reason says why).
     */
    static String verdict(StudentResult result) {
        if (result.passed()) {
            return "passed";
        }
        if (Standing.of(result) == Standing.NOT_GRADED) {
            return "not graded: tick1 could not grade this submission, so it has no result yet";
        }
        return result.scenesTotal() == 0 ? "not passed: no scene could be run"
                : "not passed: " + result.scenesPassed() + " of " + result.scenesTotal() + " scenes matched";
    }

    /**
     * What the grade found to reread, each once, in the order the explanations name it, at most
     * {@value #MOST_TO_REREAD}: "handout section 5." as "Handout section 5.". The grader names a
     * section for the properties its probes found wrong (or for an image a catalogue entry matches
     * exactly), never for a candidate it is unsure of.
     */
    static List<String> rereading(StudentResult result) {
        Set<String> lines = new LinkedHashSet<>();
        result.findings().reread().forEach(section -> lines.add(capitalised(section.strip())));
        return lines.stream().limit(MOST_TO_REREAD).toList();
    }

    /**
     * The reason's prose, as a page of feedback gives it: the row's pointers to "the feedback" (the
     * shortened list of facts, an unsure diagnosis) point, here, to the scenes below.
     */
    static String seeBelow(String prose) {
        return prose.replace(SEE_THE_FEEDBACK, " (see the scenes below)").replace(CohortOutputs.REST,
                " (more in the scenes below)");
    }

    static String html(StudentResult result) {
        Submission student = result.submission();
        ReasonText why = ReasonText.of(result.reason());
        String who = Html.escape(student.fullName());
        StringBuilder out = new StringBuilder(8192);
        out.append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n")
                .append("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n")
                .append("<title>Tick 1 feedback: ").append(who).append("</title>\n<style>\n")
                .append(STYLE).append("</style>\n</head>\n<body>\n")
                .append("<h1>Tick 1 feedback for <bdi>").append(who).append("</bdi></h1>\n")
                .append("<p class=\"id\">Participant <bdi>").append(Html.escape(student.id())).append("</bdi></p>\n")
                .append("<p class=\"verdict ").append(Standing.of(result).style()).append("\">")
                .append(Html.escape(capitalised(verdict(result)))).append("</p>\n")
                .append("<h2>Why</h2>\n<p class=\"reason\">")
                .append(Html.escape(seeBelow(why.prose()))).append("</p>\n").append(why.quotedHtml());
        List<String> rereading = rereading(result);
        if (!rereading.isEmpty()) {
            out.append("<h2>What to reread</h2>\n<ul class=\"reread\">\n");
            rereading.forEach(line -> out.append("<li>").append(Html.escape(line)).append("</li>\n"));
            out.append("</ul>\n");
        }
        if (!result.scenes().isEmpty()) {
            out.append("<h2>Scenes</h2>\n");
        }
        List<String> titles = sceneTitles(result.scenes());
        boolean legendShown = false;
        for (int i = 0; i < result.scenes().size(); i++) {
            SceneResult scene = result.scenes().get(i);
            out.append("<section class=\"scene ").append(scene.passed() ? "pass" : "fail").append("\">\n<h3>")
                    .append(Html.escape(titles.get(i))).append(": ").append(scene.passed() ? "passed" : "failed")
                    .append("</h3>\n");
            if (!scene.explanation().isEmpty()) {
                out.append("<pre class=\"explanation\">");
                scene.explanation().forEach(line -> out.append(Html.escape(line)).append('\n'));
                out.append("</pre>\n");
            }
            List<String> images = images(scene);
            if (!images.isEmpty()) {
                out.append("<div class=\"images\">\n");
                figure(out, scene.files().heatMap(), "Heat map of the differences");
                figure(out, scene.files().yours(), "Your image");
                figure(out, scene.files().expected(), "Expected image");
                out.append("</div>\n");
                if (!legendShown && scene.files().heatMap() != null) {
                    out.append(HeatMapKey.html());
                    legendShown = true;
                }
            }
            out.append("</section>\n");
        }
        return out.append("</body>\n</html>\n").toString();
    }

    private static void figure(StringBuilder out, String file, String caption) {
        if (file != null) {
            String url = Html.relativeUrl(file);
            out.append("<figure><a href=\"").append(url).append("\"><img src=\"").append(url).append("\" alt=\"")
                    .append(caption).append("\"></a><figcaption>").append(caption).append(" (")
                    .append(Html.escape(file)).append(")</figcaption></figure>\n");
        }
    }

    static String text(StudentResult result) {
        Submission student = result.submission();
        ReasonText why = ReasonText.of(result.reason());
        StringBuilder out = new StringBuilder(4096);
        out.append("Tick 1 feedback for ").append(Html.plain(student.fullName())).append(" (participant ")
                .append(Html.plain(student.id())).append(")\n\nResult: ").append(verdict(result))
                .append("\n\nWhy\n").append(indented(Html.plain(seeBelow(why.prose()))));
        why.quoted().forEach(line -> out.append("  ").append(Html.plain(line)).append('\n'));
        List<String> rereading = rereading(result);
        if (!rereading.isEmpty()) {
            out.append("\nWhat to reread\n");
            rereading.forEach(line -> out.append("  - ").append(Html.plain(line)).append('\n'));
        }
        List<String> titles = sceneTitles(result.scenes());
        boolean anyImages = false;
        for (int i = 0; i < result.scenes().size(); i++) {
            SceneResult scene = result.scenes().get(i);
            out.append('\n').append(Html.plain(titles.get(i))).append(": ").append(scene.passed() ? "passed" : "failed")
                    .append('\n');
            scene.explanation().forEach(line -> out.append("  ").append(Html.plain(line)).append('\n'));
            List<String> images = images(scene);
            if (!images.isEmpty()) {
                anyImages = true;
                out.append("  images beside this file: ").append(Html.plain(String.join(", ", images))).append('\n');
            }
        }
        if (anyImages) {
            out.append('\n').append(HeatMapKey.text()).append('\n');
        }
        return out.toString();
    }

    private static String indented(String paragraph) {
        StringBuilder out = new StringBuilder();
        paragraph.lines().forEach(line -> out.append("  ").append(line).append('\n'));
        return out.toString();
    }

    private static String capitalised(String text) {
        return text.isEmpty() ? text : Character.toUpperCase(text.charAt(0)) + text.substring(1);
    }
}
