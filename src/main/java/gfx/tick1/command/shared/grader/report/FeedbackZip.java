package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.StudentResult;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

/**
 * {@code feedback.zip}: every student's feedback files in a folder named as the student's folder in
 * the submissions download, the layout Moodle's "Upload multiple feedback files in a zip" reads
 * (it finds the participant by the number in a folder named {@code Full Name_<id>_...}).
 */
final class FeedbackZip {

    static final String NAME = ReportFiles.FEEDBACK_ZIP;

    private FeedbackZip() {
    }

    /** The files of one student's feedback folder that go back to the student, in the zip's order. */
    static List<String> returnedFiles(StudentResult result) {
        List<String> files = new ArrayList<>(List.of(FeedbackPage.HTML, FeedbackPage.TEXT));
        result.scenes().forEach(scene -> files.addAll(FeedbackPage.images(scene)));
        return files;
    }

    /**
     * Writes the zip from the feedback folders under {@code report}. Only the files the feedback
     * names are taken, and only regular files (not links), so nothing else that lies in a folder
     * reaches a student.
     */
    static void write(Path report, List<StudentResult> results, OutputStream target) throws IOException {
        ZipOutputStream zip = new ZipOutputStream(target);
        // Most of the bytes are PNGs, deflated already: the quickest level packs them as well as any.
        zip.setLevel(1);
        for (StudentResult result : results) {
            String folder = result.submission().folder();
            Path source = ReportFiles.feedbackFolder(report, folder);
            for (String file : returnedFiles(result)) {
                Path path = source.resolve(file);
                if (Files.isRegularFile(path, LinkOption.NOFOLLOW_LINKS)) {
                    zip.putNextEntry(new ZipEntry(folder + "/" + file));
                    Files.copy(path, zip);
                    zip.closeEntry();
                }
            }
        }
        zip.finish();
    }
}
