package gfx.tick1.command.shared.grader.report;

import static java.nio.file.LinkOption.NOFOLLOW_LINKS;

import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.FindingText;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.engine.io.IoErrors;
import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * The grader's part of a cohort's report folder: each student's mark, and the images of the
 * failing scenes placed in the student's feedback folder, where the pages of
 * {@link gfx.tick1.command.shared.grader.report.CohortReport} show them, each written whole by {@link ReportFiles}.
 */
public final class CohortOutputs {

    private CohortOutputs() {
    }

    /**
     * The most characters of a reason the report keeps, whatever the student's files held: more than
     * tick1's own words of two findings, so that only a student's text (an exception's message) meets it.
     */
    static final int MAX_REASON = 2_000;
    /** Where the rest of a reason cut at {@link #MAX_REASON} is, in every place that shows the reason. */
    static final String REST = " (more in feedback.html)";
    /**
     * The most characters of one explanation line (one finding: more than tick1's longest), and the
     * most lines of one scene's explanation.
     */
    static final int MAX_LINE = 2_000;
    static final int MAX_LINES = 60;
    /** How an explanation's line that sends the student to the handout starts. */
    private static final String REREAD = "reread:";
    /** The most characters of a name or id shown. */
    static final int MAX_NAME = 200;

    /**
     * Copies each result's images (the files its scene results name) from the folder where its
     * result is stored, {@code images} (in the same order; null for none), into its feedback folder.
     *
     * @return the students whose images could not be placed, each with why; the others' are placed
     */
    public static List<Unwritten> placeImages(List<StudentResult> results, List<Path> images, Path report) {
        List<Unwritten> unwritten = new ArrayList<>();
        for (int i = 0; i < results.size(); i++) {
            String student = results.get(i).submission().folder();
            try {
                placeImages(results.get(i), images.get(i), ReportFiles.ownFeedbackFolder(report, student));
            } catch (IOException e) {
                unwritten.add(new Unwritten(student, IoErrors.reason(e)));
            }
        }
        return List.copyOf(unwritten);
    }

    private static void placeImages(StudentResult result, Path stored, Path folder) throws IOException {
        removeImagesNotNamed(folder, result);
        for (SceneResult scene : result.scenes()) {
            for (String image : scene.files().named()) {
                if (stored != null) {
                    Path source = stored.resolve(image);
                    ReportFiles.write(folder.resolve(image), out -> Files.copy(source, out));
                }
            }
        }
    }

    /**
     * Deletes the PNGs of a student's feedback folder that the result does not name: the images of
     * an earlier failure the student has since mended must not go back to them.
     */
    private static void removeImagesNotNamed(Path folder, StudentResult result) throws IOException {
        Set<String> named = new HashSet<>();
        for (SceneResult scene : result.scenes()) {
            named.addAll(scene.files().named());
        }
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder, "*.png")) {
            for (Path file : files) {
                if (!named.contains(file.getFileName().toString()) && Files.isRegularFile(file, NOFOLLOW_LINKS)) {
                    Files.delete(file);
                }
            }
        }
    }

    /**
     * The results as the report takes them: each submission's folder name made one plain path
     * element ({@link ReportFiles#plainName}), different from the others' (a name from a download
     * can hold a backslash or a control character, and after that change two names could meet;
     * Moodle's own names pass unchanged) and no longer than a file system takes ({@link
     * ReportFiles#fitted}: a long name keeps Moodle's {@code _<id>_} and plugin part), and every
     * text bounded: the reason to {@link #MAX_REASON} characters, the name and id to {@link
     * #MAX_NAME}, each explanation to {@link #MAX_LINES} lines of {@link #MAX_LINE}; so no cell,
     * page or file of the report grows with what a student's archive holds.
     */
    public static List<StudentResult> forReport(List<StudentResult> results) {
        Set<String> taken = new HashSet<>();
        List<StudentResult> plain = new ArrayList<>();
        for (StudentResult result : results) {
            Submission submission = result.submission();
            String plainFolder = ReportFiles.plainName(submission.folder());
            String folder = ReportFiles.fitted(plainFolder, submission.id(), "");
            for (int n = 2; !taken.add(folder); n++) {
                folder = ReportFiles.fitted(plainFolder, submission.id(), "_" + n);
            }
            List<SceneResult> scenes = result.scenes().stream().map(scene -> new SceneResult(
                    CellText.bounded(scene.name(), MAX_NAME), scene.hidden(), scene.passed(),
                    bounded(scene.explanation()), scene.files())).toList();
            StudentResult.Summary summary = new StudentResult.Summary(result.passed(), result.scenesPassed(),
                    result.scenesTotal(), bounded(result.diagnosis()),
                    FindingText.fitted(result.reason(), MAX_REASON, REST));
            plain.add(new StudentResult(new Submission(folder, CellText.bounded(submission.id(), MAX_NAME),
                    CellText.bounded(submission.fullName(), MAX_NAME), submission.sphere(), submission.renderer(),
                    submission.problem()), summary, scenes, result.time(),
                    result.findings().mapText(text -> CellText.bounded(text, MAX_LINE))));
        }
        return plain;
    }


    /** A named mistake's label bounded to {@link #MAX_NAME}; an outcome's is short already. */
    private static Category bounded(Category category) {
        return category instanceof Category.Mistake mistake
                ? new Category.Mistake(CellText.bounded(mistake.label(), MAX_NAME)) : category;
    }

    /** At most {@link #MAX_LINES} lines of an explanation, each bounded; its "reread:" lines are always kept. */
    private static List<String> bounded(List<String> lines) {
        List<String> reread = lines.stream().filter(line -> line.startsWith(REREAD)).limit(MAX_LINES / 2).toList();
        List<String> kept = new ArrayList<>();
        int left = lines.size() - reread.size();
        for (String line : lines) {
            if (kept.size() < MAX_LINES - reread.size() && !line.startsWith(REREAD)) {
                kept.add(CellText.bounded(line, MAX_LINE));
                left--;
            }
        }
        if (left > 0) {
            kept.add(String.format(java.util.Locale.ROOT, "(and %,d more lines)", left));
        }
        reread.forEach(line -> kept.add(CellText.bounded(line, MAX_LINE)));
        return List.copyOf(kept);
    }
}
