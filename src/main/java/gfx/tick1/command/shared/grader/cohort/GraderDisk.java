package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Whether a failed grade may be the grader's own disk's doing rather than the student's: a run
 * whose files could not be written (the JVM's, javac's, the harness's images) fails as a wrong
 * or missing image would. Such a result is not stored; the submission is "not graded", and the
 * next run of the same command grades it again.
 */
final class GraderDisk {

    /** What the kernel's ENOSPC and EDQUOT read as, in an exception or a compiler's message. */
    private static final String[] FULL_WORDS = {"No space left on device", "Disk quota exceeded"};

    private GraderDisk() {
    }

    /**
     * Null when {@code result}, a failure, cannot be the disk's doing; else why it may be, in words
     * for the course staff: the folder {@code work} is on has less free space than one run may
     * write ({@link WorkFolder#RUN_SPACE}), or the result's words say a disk was full.
     */
    static String shortOfSpace(Path work, StudentResult result) {
        long free;
        try {
            free = Files.getFileStore(work).getUsableSpace();
        } catch (IOException e) {
            return "the free space of the grader's temporary folder cannot be read (" + e.getMessage() + ")";
        }
        if (free < WorkFolder.RUN_SPACE) {
            return "the grader's temporary folder has only " + (free >> 20) + " MiB free, less than the "
                    + (WorkFolder.RUN_SPACE >> 20) + " MiB a run may need: free some space and grade again";
        }
        for (String word : FULL_WORDS) {
            if (result.reason().contains(word) || result.scenes().stream()
                    .anyMatch(scene -> scene.explanation().stream().anyMatch(line -> line.contains(word)))) {
                return "a disk was full while it was graded (\"" + word + "\"): free some space and grade again";
            }
        }
        return null;
    }
}
