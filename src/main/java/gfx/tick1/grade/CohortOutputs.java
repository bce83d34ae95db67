package gfx.tick1.grade;

import gfx.tick1.grade.cohort.StudentResult;
import gfx.tick1.grade.cohort.StudentResult.SceneResult;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Locale;

/**
 * What a cohort grade leaves in the report folder, made from every result: {@code grades.csv} in
 * the form of Moodle's offline grading worksheet, a feedback folder per student with a page and
 * the images of the failing scenes, and {@code index.html}. Each file is written beside its place
 * and renamed into it, so that none is ever half-written. The plain forms here are what the
 * worksheet filler and the report pages of {@code gfx.tick1.grade.cohort} refine.
 */
final class CohortOutputs {

    /** The worksheet's columns, as Moodle writes and reads them. */
    static final String HEADER = "Identifier,Full name,Email address,Status,Grade,Maximum Grade,Grade can be changed,"
            + "Last modified (submission),Last modified (grade),Feedback comments";

    private CohortOutputs() {
    }

    /** The mark for {@code result}: the pass mark, or with {@code perScene} the share of scenes passed of it. */
    static double grade(StudentResult result, double maxGrade, boolean perScene) {
        if (perScene) {
            return result.scenesTotal() == 0 ? 0 : maxGrade * result.scenesPassed() / result.scenesTotal();
        }
        return result.passed() ? maxGrade : 0;
    }

    /** A mark as the worksheet writes it: two decimals, a point. */
    static String mark(double grade) {
        return String.format(Locale.ROOT, "%.2f", grade);
    }

    /** Writes grades.csv: one row per result, in the order given. */
    static void writeGrades(List<StudentResult> results, Path report, double maxGrade, boolean perScene)
            throws IOException {
        StringBuilder csv = new StringBuilder(HEADER).append("\r\n");
        for (StudentResult result : results) {
            csv.append(String.join(",", cell("Participant " + result.submission().id()),
                    cell(result.submission().fullName()), "", "", mark(grade(result, maxGrade, perScene)),
                    mark(maxGrade), "Yes", "", "", cell(result.reason()))).append("\r\n");
        }
        writeAtomically(report.resolve("grades.csv"), csv.toString());
    }

    /** The feedback folder of {@code result} in {@code report}: feedback/ and the download's folder name. */
    static Path feedbackFolder(Path report, StudentResult result) {
        return report.resolve("feedback").resolve(safe(result.submission().folder()));
    }

    /**
     * Copies each result's images (the files its scene results name) from the folder where its
     * result is stored, {@code images} (in the same order; null for none), into its feedback folder.
     */
    static void placeImages(List<StudentResult> results, List<Path> images, Path report) throws IOException {
        for (int i = 0; i < results.size(); i++) {
            Path folder = Files.createDirectories(feedbackFolder(report, results.get(i)));
            for (SceneResult scene : results.get(i).scenes()) {
                for (String image : new String[] {scene.heatMap(), scene.yours(), scene.expected()}) {
                    if (image != null && images.get(i) != null) {
                        Path temporary = writing(folder.resolve(image));
                        Files.copy(images.get(i).resolve(image), temporary, StandardCopyOption.REPLACE_EXISTING);
                        Files.move(temporary, folder.resolve(image), StandardCopyOption.REPLACE_EXISTING,
                                StandardCopyOption.ATOMIC_MOVE);
                    }
                }
            }
        }
    }

    /** Writes feedback/FOLDER/feedback.html for each result, beside the images {@link #placeImages} put there. */
    static void writeFeedback(List<StudentResult> results, Path report) throws IOException {
        for (StudentResult result : results) {
            Path folder = Files.createDirectories(feedbackFolder(report, result));
            StringBuilder page = new StringBuilder("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                    + "<title>Tick 1 feedback</title></head><body>\n<h1>Tick 1: ")
                    .append(result.passed() ? "passed" : "not yet passed").append("</h1>\n<p>")
                    .append(html(result.reason())).append("</p>\n");
            for (SceneResult scene : result.scenes()) {
                page.append("<h2>").append(html(scene.name())).append(scene.passed() ? ": pass" : ": fail")
                        .append("</h2>\n");
                if (!scene.explanation().isEmpty()) {
                    page.append("<pre>").append(html(String.join("\n", scene.explanation()))).append("</pre>\n");
                }
                for (String image : new String[] {scene.heatMap(), scene.yours(), scene.expected()}) {
                    if (image != null) {
                        page.append("<img src=\"").append(html(image)).append("\" alt=\"").append(html(image))
                                .append("\">\n");
                    }
                }
            }
            writeAtomically(folder.resolve("feedback.html"), page.append("</body></html>\n").toString());
        }
    }

    /** Writes index.html: how many passed, and one row per student. */
    static void writeIndex(List<StudentResult> results, Path report) throws IOException {
        long passed = results.stream().filter(StudentResult::passed).count();
        StringBuilder page = new StringBuilder("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                + "<title>Tick 1 grades</title></head><body>\n<h1>Tick 1: ").append(passed).append(" of ")
                .append(results.size()).append(" passed</h1>\n<table>\n<tr><th>student</th><th>result</th>"
                        + "<th>diagnosis</th><th>reason</th><th>seconds</th></tr>\n");
        for (StudentResult result : results) {
            page.append("<tr><td><a href=\"feedback/").append(html(safe(result.submission().folder())))
                    .append("/feedback.html\">").append(html(result.submission().fullName())).append("</a></td><td>")
                    .append(result.passed() ? "pass" : "fail").append("</td><td>").append(html(result.diagnosis()))
                    .append("</td><td>").append(html(result.reason())).append("</td><td>")
                    .append(String.format(Locale.ROOT, "%.1f", result.time().toMillis() / 1000.0))
                    .append("</td></tr>\n");
        }
        writeAtomically(report.resolve("index.html"), page.append("</table></body></html>\n").toString());
    }

    /** A folder name from the download, as a single safe path element. */
    static String safe(String folder) {
        String name = folder.replaceAll("[/\\\\\\x00-\\x1f]", "_");
        return name.isEmpty() || name.equals(".") || name.equals("..") ? "_" + name : name;
    }

    private static String cell(String text) {
        return text.contains(",") || text.contains("\"") || text.contains("\n") || text.contains("\r")
                ? "\"" + text.replace("\"", "\"\"") + "\"" : text;
    }

    private static String html(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }

    /** The temporary file beside {@code target} that is renamed over it once complete. */
    private static Path writing(Path target) {
        return target.resolveSibling("." + target.getFileName() + ".writing");
    }

    /** Writes {@code text} to a temporary file beside {@code target}, then renames it over the target. */
    static void writeAtomically(Path target, String text) throws IOException {
        Path temporary = writing(target);
        Files.writeString(temporary, text, StandardCharsets.UTF_8);
        Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }
}
