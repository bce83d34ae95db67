package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.UUID;
import java.util.concurrent.TimeUnit;

/**
 * Whether a failed grade may be the grader's own disk's doing rather than the student's: a run
 * whose files could not be written (the JVM's, javac's, the harness's images) fails as a wrong
 * or missing image would. Such a result is not stored; the submission is "not graded", and the
 * next run of the same command grades it again.
 *
 * <p>It is decided from what the run hit: the disk just after it failed. A disk that still has room for
 * tick1's own part of a run ({@link #FULL_BYTES}, {@link #FULL_FILES}) was not full when the run wrote, so the
 * failure is the student's, however much less room there is than the output limit
 * ({@link WorkFolder#RUN_SPACE}) allows a run to use. A disk full only with the run's own files (its output
 * folder, which it may fill faster than its output is counted) was filled by the run: its failure is its own.
 * A disk that stays full once the run's files are gone leaves that student not graded, even when it was that
 * full before the run began: another job may have filled it and hold it full, and a correct run fails on it as
 * a wrong one does.
 *
 * <p>It is decided from the grader's disk alone, as the file system reports it after the failure,
 * never from the result's words: those are the student's to choose (an exception's message, a
 * source line quoted in a compile error). Free bytes come from Java; free inodes from the system's
 * stat (Java has no call for them), and where stat cannot tell, from a file and a folder made in
 * the work folder: that they can be made shows that inodes remain, if not how many.
 */
final class GraderDisk {

    /** The system's stat (coreutils, which every Debian has): its file system form prints free and all inodes. */
    private static final Path STAT = Path.of("/usr/bin/stat");
    /** How long stat may take before the grader asks the file system by making a file instead. */
    static final int STAT_SECONDS = 5;
    /** The prefix of what is made to see whether the file system still takes files. */
    private static final String PROBE = ".tick1-disk-probe-";

    /**
     * Free bytes below which the disk is full: less than tick1's own part of a run writes (the JVM's
     * files, javac's class files of a correct submission, the harness's images).
     */
    static final long FULL_BYTES = 16L << 20;
    /** Free files and folders below which the disk is full: fewer than tick1's own part of a run makes. */
    static final long FULL_FILES = 256;

    private GraderDisk() {
    }

    /**
     * Null when the folder {@code work} is on is not full just after a failed run; else why the
     * failure may be the disk's doing, in words for the course staff: fewer free bytes than
     * {@link #FULL_BYTES}, fewer free files and folders than {@link #FULL_FILES}, or, where their
     * number cannot be read, no room for one more.
     */
    static String shortOfSpace(Path work) throws InterruptedException {
        return shortOfSpace(work, STAT);
    }

    /**
     * As {@link #shortOfSpace(Path)} just after a failed run, whose own files are in {@code run}: null too
     * when the disk is full only with them, the run having filled it itself. When the disk is full, the run's
     * folder is deleted (it would be after the grade in any case) and the disk asked again.
     */
    static String shortOfSpaceBeyond(Path work, Path run) throws InterruptedException {
        return shortOfSpaceBeyond(work, run, STAT);
    }

    /** {@link #shortOfSpaceBeyond(Path, Path)}, with the stat at {@code stat}. */
    static String shortOfSpaceBeyond(Path work, Path run, Path stat) throws InterruptedException {
        String why = shortOfSpace(work, stat);
        if (why == null) {
            return null;
        }
        WorkFolder.delete(run);
        return shortOfSpace(work, stat) == null ? null : why;
    }

    /** {@link #shortOfSpace(Path)}, with the stat at {@code stat}. */
    static String shortOfSpace(Path work, Path stat) throws InterruptedException {
        // statvfs on the folder itself (File's), not Files.getFileStore, which looks the folder's mount up
        // in the mount table and finds none in a chroot, whose mounts are named as outside it.
        long free = work.toFile().getUsableSpace();
        if (free < FULL_BYTES) {
            return "the grader's temporary folder was full when its run failed (" + (free >> 20) + " MiB free, less "
                    + "than the " + (FULL_BYTES >> 20) + " MiB tick1's own part of a run needs): free some space and "
                    + "grade again";
        }
        long[] inodes = inodes(work, stat);
        if (inodes == null || inodes[1] == 0) {
            return takesAFileAndAFolder(work);
        }
        if (inodes[0] < FULL_FILES) {
            return "the grader's temporary folder was full when its run failed (room for only " + inodes[0]
                    + " more files, fewer than the " + FULL_FILES + " tick1's own part of a run makes): free some and "
                    + "grade again";
        }
        return null;
    }

    /**
     * The free and total inodes of the file system {@code work} is on (0 total where the file system
     * keeps no count), as {@code program} prints them; null when it cannot tell: missing, failing, or
     * printing another form. The short options are GNU's and BusyBox's alike.
     */
    private static long[] inodes(Path work, Path program) throws InterruptedException {
        String printed;
        try {
            Process stat = new ProcessBuilder(program.toString(), "-f", "-c", "%d %c", work.toString())
                    .redirectErrorStream(true).start();
            stat.getOutputStream().close();
            // A file system that does not answer (a hung network mount) must not hang the grade: its
            // few bytes of output fit in the pipe, so they are read once it has ended.
            if (!stat.waitFor(STAT_SECONDS, TimeUnit.SECONDS)) {
                stat.destroyForcibly();
                return null;
            }
            printed = new String(stat.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
            if (stat.exitValue() != 0) {
                return null;
            }
        } catch (IOException e) {
            return null;
        }
        String[] fields = printed.split("\\s+");
        try {
            return fields.length == 2 ? new long[] {Long.parseLong(fields[0]), Long.parseLong(fields[1])} : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** Null when a file and a folder can be made (and are deleted) in {@code work}; else why not. */
    private static String takesAFileAndAFolder(Path work) {
        String name = PROBE + UUID.randomUUID();
        try {
            Files.delete(Files.createFile(work.resolve(name)));
            Files.delete(Files.createDirectory(work.resolve(name)));
            return null;
        } catch (IOException e) {
            return "the grader's temporary folder takes no new file or folder (" + e.getMessage()
                    + "): free some and grade again";
        }
    }
}
