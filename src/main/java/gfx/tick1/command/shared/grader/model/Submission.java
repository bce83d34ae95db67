package gfx.tick1.command.shared.grader.model;

import java.util.List;

/**
 * One student's submission, as found in a cohort's download: who it belongs to and the two files
 * the tick asks for, or why they could not be found.
 *
 * @param folder   the top-level folder of the download the submission came from, as named there
 *                 (Moodle: {@code Full Name_<participant id>_assignsubmission_file}, with a trailing {@code _} before
 *                 Moodle 4.1)
 * @param id       the participant id from a Moodle folder name, else the folder's name
 * @param fullName the name from a Moodle folder name, else the folder's name
 * @param sphere   the student's Sphere.java, or null when {@code problem} says why there is none
 * @param renderer the student's Renderer.java, or null when {@code problem} says why there is none
 * @param problem  why the submission cannot be graded as it stands (a missing file, two candidates
 *                 for one file, an empty folder, an archive entry refused), or null; a submission
 *                 with a problem is still a graded result, with this as its reason
 */
public record Submission(String folder, String id, String fullName, SourceFile sphere, SourceFile renderer,
        String problem) {

    /**
     * A file found in the submission.
     *
     * @param path    where it was in the student's folder, for messages ({@code src/Sphere.java},
     *                {@code work.zip!/Sphere.java})
     * @param content its bytes, as submitted
     */
    public record SourceFile(String path, byte[] content) {
    }

    /** Both files, in the order the tick lists them; empty when {@code problem} is set. */
    public List<SourceFile> files() {
        return problem != null ? List.of() : List.of(sphere, renderer);
    }
}
