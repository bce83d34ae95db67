package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Whether a failed grade may be the grader's own disk's doing rather than the student's: a run
 * whose files could not be written (the JVM's, javac's, the harness's images) fails as a wrong
 * or missing image would. Such a result is not stored; the submission is "not graded", and the
 * next run of the same command grades it again.
 *
 * <p>It is decided from the grader's disk alone, as the file system reports it after the failure,
 * never from the result's words: those are the student's to choose (an exception's message, a
 * source line quoted in a compile error).
 */
final class GraderDisk {

    /** GNU stat's file system form: free inodes, then all inodes (0 where the file system has no count). */
    private static final String STAT = "/usr/bin/stat";

    private GraderDisk() {
    }

    /**
     * Null when the folder {@code work} is on has room for one run; else why a failure there may
     * be the disk's doing, in words for the course staff: fewer free bytes than one run may write
     * ({@link WorkFolder#RUN_SPACE}), or fewer free files and folders than it may make
     * ({@link WorkFolder#RUN_FILES}).
     */
    static String shortOfSpace(Path work) throws InterruptedException {
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
        long[] inodes;
        try {
            inodes = inodes(work);
        } catch (IOException e) {
            return "the free files of the grader's temporary folder cannot be read (" + e.getMessage() + ")";
        }
        if (inodes[1] > 0 && inodes[0] < WorkFolder.RUN_FILES) {
            return "the grader's temporary folder has room for only " + inodes[0] + " more files, fewer than the "
                    + WorkFolder.RUN_FILES + " a run may make: free some and grade again";
        }
        return null;
    }

    /** The free and total inodes of the file system {@code work} is on (statvfs; Java has no call for it). */
    private static long[] inodes(Path work) throws IOException, InterruptedException {
        Process stat = new ProcessBuilder(STAT, "--file-system", "--format=%d %c", work.toString())
                .redirectErrorStream(true).start();
        stat.getOutputStream().close();
        String printed = new String(stat.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        if (stat.waitFor() != 0) {
            throw new IOException(printed);
        }
        String[] fields = printed.split("\\s+");
        try {
            return new long[] {Long.parseLong(fields[0]), Long.parseLong(fields[1])};
        } catch (NumberFormatException | ArrayIndexOutOfBoundsException e) {
            throw new IOException("stat printed \"" + printed + "\"", e);
        }
    }
}
