package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.lookalike.Lookalike;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.engine.io.IoErrors;
import java.io.IOException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import java.util.regex.Pattern;

/**
 * The pages a cohort's grading leaves in its report folder:
 * <ul>
 * <li>{@code feedback/<folder>/feedback.html} and {@code feedback.txt} for each student, beside the
 *     images the grader wrote there (named in each {@link SceneResult});
 * <li>{@code feedback.zip}, those folders as Moodle takes feedback files back;
 * <li>{@code index.html}, the cohort at a glance.
 * </ul>
 * Every file is written whole and then renamed into place, the index last, so a run stopped part
 * way leaves each page as it was or complete, and the index never links to a page not yet written.
 */
public final class CohortReport {

    /** The report folder's page of the whole cohort. */
    public static final String INDEX = "index.html";

    /** The names tick1 gives its pages and images (1-tick1-diff.png) in a student's feedback folder. */
    private static final String NAMES = "(" + Pattern.quote(FeedbackPage.HTML) + "|" + Pattern.quote(FeedbackPage.TEXT)
            + "|\\d+-.+-(diff|yours|expected)\\.png)";
    /** Those names, and those of the temporary files they are written as ({@code .feedback.html.RANDOM.tmp}). */
    private static final Pattern WRITTEN = Pattern.compile(NAMES + "|\\." + NAMES + "\\.\\d+\\.tmp");

    private CohortReport() {
    }

    /**
     * Writes (or rewrites) the feedback files, the zip and the index for {@code results}, in the
     * order given (the index's table starts in that order).
     *
     * @param reportFolder the report folder; it and the feedback folders are made when missing
     * @param given        every student's result; each submission's {@code folder} must be one plain
     *                     folder name, different from every other, as must each image's file name
     * @param grade        the mark to show for a result, as the gradebook has it (for example "1.00");
     *                     the index links to {@code grades.csv} when it is already in the folder
     * @return the students whose feedback files could not be written (a name the file system refuses, a file
     *                     where their folder belongs), each with why: they are left out of feedback.zip, and the
     *                     rest of the report is written
     * @throws IllegalArgumentException when a folder or file name is not a plain name, or two
     *                     results share a folder; nothing is written then
     * @throws IOException when a file of the whole cohort's cannot be written; the files written before it stay
     */
    public static List<Unwritten> write(Path reportFolder, List<StudentResult> given,
            Function<StudentResult, String> grade) throws IOException {
        return write(reportFolder, given, grade, null);
    }

    /**
     * As {@link #write(Path, List, Function)}, with the cohort's look-alikes ({@code lookalikes.csv},
     * their pages and the index's section), or without them when {@code lookalikes} is null.
     */
    public static List<Unwritten> write(Path reportFolder, List<StudentResult> given,
            Function<StudentResult, String> grade, List<Lookalike> lookalikes) throws IOException {
        checkNames(given);
        List<String> grades = given.stream().map(grade).toList();
        Files.createDirectories(reportFolder);
        List<StudentResult> results = new ArrayList<>();
        List<StudentResult> written = new ArrayList<>();
        List<Unwritten> unwritten = new ArrayList<>();
        for (StudentResult result : given) {
            StudentResult shown;
            try {
                // The folder made (a link there replaced) before any file in it is looked at.
                Path folder = ReportFiles.ownFeedbackFolder(reportFolder, result.submission().folder());
                shown = withImagesOnDisk(folder, result);
                ReportFiles.write(folder.resolve(FeedbackPage.HTML), FeedbackPage.html(shown));
                ReportFiles.write(folder.resolve(FeedbackPage.TEXT), FeedbackPage.text(shown));
                written.add(shown);
            } catch (IOException e) {
                unwritten.add(new Unwritten(result.submission().folder(), IoErrors.reason(e)));
                shown = withImagesOnDisk(null, result);
            }
            results.add(shown);
        }
        removeOthers(reportFolder, given);
        ReportFiles.write(reportFolder.resolve(FeedbackZip.NAME), out -> FeedbackZip.write(reportFolder, written, out));
        List<String> beside = new ArrayList<>(List.of(FeedbackZip.NAME));
        if (Files.isRegularFile(reportFolder.resolve(ReportFiles.GRADES), LinkOption.NOFOLLOW_LINKS)) {
            beside.add(ReportFiles.GRADES);
        }
        String sections = YearAtAGlance.html(results, grades);
        if (lookalikes != null) {
            sections += LookalikeSection.write(reportFolder, lookalikes);
            beside.add(LookalikesCsv.NAME);
        }
        ReportFiles.write(reportFolder.resolve(INDEX), CohortPage.html(results, grades, beside, sections));
        return List.copyOf(unwritten);
    }

    /**
     * Deletes the feedback folders of students not among {@code results} (no longer in the download): the files
     * tick1 writes there ({@link #WRITTEN}), then the folder if nothing else is left in it. What the course staff
     * put there (a marker's notes, a folder of their own) is theirs, never deleted.
     */
    private static void removeOthers(Path reportFolder, List<StudentResult> results) throws IOException {
        Set<String> folders = new HashSet<>();
        results.forEach(result -> folders.add(result.submission().folder()));
        try (DirectoryStream<Path> students = Files.newDirectoryStream(reportFolder.resolve(ReportFiles.FEEDBACK))) {
            for (Path student : students) {
                if (folders.contains(student.getFileName().toString())
                        || !Files.isDirectory(student, LinkOption.NOFOLLOW_LINKS)) {
                    continue;
                }
                try (DirectoryStream<Path> files = Files.newDirectoryStream(student)) {
                    for (Path file : files) {
                        if (WRITTEN.matcher(file.getFileName().toString()).matches()
                                && !Files.isDirectory(file, LinkOption.NOFOLLOW_LINKS)) {
                            Files.delete(file);
                        }
                    }
                }
                try {
                    Files.delete(student);
                } catch (DirectoryNotEmptyException e) {
                    // a file or folder of someone else's in it: left
                }
            }
        } catch (NoSuchFileException e) {
            // no feedback folder: no student's feedback was written
        }
    }

    private static void checkNames(List<StudentResult> results) {
        Set<String> folders = new HashSet<>();
        for (StudentResult result : results) {
            String folder = result.submission().folder();
            if (!ReportFiles.isPlainName(folder) || !folders.add(folder)) {
                throw new IllegalArgumentException("submission folder \"" + folder + "\": "
                        + (ReportFiles.isPlainName(folder) ? "two results share it" : "not one plain folder name"));
            }
            for (SceneResult scene : result.scenes()) {
                for (String image : scene.files().named()) {
                    if (!ReportFiles.isPlainName(image) || isFeedbackFile(image)) {
                        throw new IllegalArgumentException("image \"" + image + "\" of " + folder
                                + ": not a plain file name of its own");
                    }
                }
            }
        }
    }

    /**
     * The result with each image that is not a file in the student's feedback folder left out
     * (the grader could not write it), so that no page shows a broken image or link to it; every
     * image, when {@code folder} is null (the student's folder could not be made).
     */
    private static StudentResult withImagesOnDisk(Path folder, StudentResult result) {
        List<SceneResult> scenes = result.scenes().stream().map(scene -> new SceneResult(scene.name(), scene.hidden(),
                scene.passed(), scene.explanation(), scene.files().map(image -> onDisk(folder, image)))).toList();
        return new StudentResult(result.submission(), new StudentResult.Summary(result.passed(), result.scenesPassed(),
                result.scenesTotal(), result.diagnosis(), result.reason()), scenes, result.time(), result.findings());
    }

    private static String onDisk(Path folder, String image) {
        return image != null && folder != null
                && Files.isRegularFile(folder.resolve(image), LinkOption.NOFOLLOW_LINKS) ? image : null;
    }

    private static boolean isFeedbackFile(String name) {
        return name.equals(FeedbackPage.HTML) || name.equals(FeedbackPage.TEXT);
    }
}
