package gfx.tick1.grade.report;

import static java.nio.file.LinkOption.NOFOLLOW_LINKS;

import gfx.tick1.grade.model.StudentResult.SceneResult;
import gfx.tick1.grade.model.StudentResult;
import gfx.tick1.grade.model.Submission;
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
 * {@link gfx.tick1.grade.report.CohortReport} show them, each written whole by {@link ReportFiles}.
 */
public final class CohortOutputs {

    private CohortOutputs() {
    }

    /** The mark for {@code result}: the pass mark, or with {@code perScene} the share of scenes passed of it. */
    public static double grade(StudentResult result, double maxGrade, boolean perScene) {
        if (perScene) {
            return result.scenesTotal() == 0 ? 0 : maxGrade * result.scenesPassed() / result.scenesTotal();
        }
        return result.passed() ? maxGrade : 0;
    }

    /** The feedback folder of {@code result} in {@code report}: feedback/ and the download's folder name. */
    static Path feedbackFolder(Path report, StudentResult result) {
        return report.resolve("feedback").resolve(safe(result.submission().folder()));
    }

    /**
     * Copies each result's images (the files its scene results name) from the folder where its
     * result is stored, {@code images} (in the same order; null for none), into its feedback folder.
     */
    public static void placeImages(List<StudentResult> results, List<Path> images, Path report) throws IOException {
        for (int i = 0; i < results.size(); i++) {
            Path folder = Files.createDirectories(feedbackFolder(report, results.get(i)));
            removeImagesNotNamed(folder, results.get(i));
            for (SceneResult scene : results.get(i).scenes()) {
                for (String image : scene.images()) {
                    if (images.get(i) != null) {
                        Path stored = images.get(i).resolve(image);
                        ReportFiles.write(folder.resolve(image), out -> Files.copy(stored, out));
                    }
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
            named.addAll(scene.images());
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
     * The results with each submission's folder name made one plain path element, different from
     * the others': a name from a download can hold a backslash or a control character, and after
     * that change two names could meet. Moodle's own names pass unchanged.
     */
    public static List<StudentResult> withPlainFolders(List<StudentResult> results) {
        Set<String> taken = new HashSet<>();
        List<StudentResult> plain = new ArrayList<>();
        for (StudentResult result : results) {
            Submission submission = result.submission();
            String folder = safe(submission.folder());
            for (int n = 2; !taken.add(folder); n++) {
                folder = safe(submission.folder()) + "_" + n;
            }
            plain.add(new StudentResult(new Submission(folder, submission.id(), submission.fullName(),
                    submission.sphere(), submission.renderer(), submission.problem()), result.passed(),
                    result.scenesPassed(), result.scenesTotal(), result.diagnosis(), result.reason(), result.scenes(),
                    result.time()));
        }
        return plain;
    }

    /** A folder name from the download, as a single safe path element. */
    static String safe(String folder) {
        String name = folder.replaceAll("[/\\\\\\x00-\\x1f]", "_");
        return name.isEmpty() || name.equals(".") || name.equals("..") ? "_" + name : name;
    }
}
