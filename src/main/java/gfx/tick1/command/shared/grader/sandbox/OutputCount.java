package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.FileVisitOption;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.EnumSet;

/**
 * The cap on what a run writes to its output folder, the one folder of the host's disk it may
 * write: counted while it runs and once more when it has ended, by a walk of the folder that
 * follows no link, goes to any depth and stops at the cap. Every entry counts by its size
 * (folders and links too: a folder keeps the space its names took, however many were deleted),
 * and a file's size bounds the disk it takes, as the sandbox refuses the calls that reserve space
 * beyond a size ({@link SeccompFilter}); a sparse file counts its holes. What the walk cannot read
 * (a folder made unreadable, or deeper than a path may be long) stops the run, as it cannot be
 * counted.
 */
final class OutputCount {

    /** The most bytes of files a run may leave in its output folder. */
    static final long BYTES_CAP = 256L << 20;
    /** The most files and folders it may make there. */
    static final int ENTRIES_CAP = 10_000;
    /** The words for a run stopped for what it wrote, by bytes and by files and folders. */
    static final String TOO_MANY_BYTES = "the program was stopped: it wrote more than " + RunLimits.size(BYTES_CAP)
            + " to its output folder";
    static final String TOO_MANY_ENTRIES = "the program was stopped: it made more than " + ENTRIES_CAP
            + " files and folders in its output folder";
    /** The words for a run stopped for what the walk could not read. */
    static final String UNCOUNTABLE = "the program was stopped: its output folder holds something the grader cannot "
            + "count (a folder made unreadable, or deeper than a path may be long)";

    private OutputCount() {
    }

    /**
     * Why {@code output} holds more than the caps allow, or what in it cannot be counted, in words
     * for the student; or null.
     */
    static String overCap(Path output) {
        if (output == null) {
            return null;
        }
        long[] bytes = {0}, entries = {0};
        boolean[] uncountable = {false};
        try {
            Files.walkFileTree(output, EnumSet.noneOf(FileVisitOption.class), Integer.MAX_VALUE,
                    new SimpleFileVisitor<>() {
                @Override
                public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attributes) {
                    return add(attributes);
                }

                @Override
                public FileVisitResult visitFile(Path file, BasicFileAttributes attributes) {
                    return add(attributes);
                }

                private FileVisitResult add(BasicFileAttributes attributes) {
                    bytes[0] += attributes.size();
                    return ++entries[0] > ENTRIES_CAP || bytes[0] > BYTES_CAP ? FileVisitResult.TERMINATE
                            : FileVisitResult.CONTINUE;
                }

                @Override
                public FileVisitResult visitFileFailed(Path file, IOException e) {
                    if (e instanceof NoSuchFileException) {
                        return FileVisitResult.CONTINUE;   // gone meanwhile
                    }
                    uncountable[0] = true;
                    return FileVisitResult.TERMINATE;
                }

                @Override
                public FileVisitResult postVisitDirectory(Path dir, IOException e) {
                    // A folder that could not be listed to its end (made unreadable as it was listed).
                    uncountable[0] |= e != null && !(e instanceof NoSuchFileException);
                    return uncountable[0] ? FileVisitResult.TERMINATE : FileVisitResult.CONTINUE;
                }
            });
        } catch (NoSuchFileException e) {
            return null;   // the folder itself is gone: nothing in it to count
        } catch (IOException | RuntimeException e) {
            return UNCOUNTABLE;
        }
        if (bytes[0] > BYTES_CAP) {
            return TOO_MANY_BYTES;
        }
        if (entries[0] > ENTRIES_CAP) {
            return TOO_MANY_ENTRIES;
        }
        return uncountable[0] ? UNCOUNTABLE : null;
    }
}
