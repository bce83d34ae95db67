package gfx.tick1.grade.sandbox;

import java.io.IOException;
import java.nio.file.FileVisitOption;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.EnumSet;

/**
 * The cap on what a run writes to its output folder, the one folder of the host's disk it may
 * write: counted while it runs, by a walk of the folder that follows no link and stops at the cap.
 */
final class OutputCount {

    /** The most bytes of files a run may leave in its output folder. */
    static final long BYTES_CAP = 256L << 20;
    /** The most files and folders it may make there. */
    static final int ENTRIES_CAP = 10_000;
    /** How deep the walk goes: far deeper than the harness writes. */
    private static final int DEPTH = 64;

    private OutputCount() {
    }

    /** Why {@code output} holds more than the caps allow, in words for the student, or null. */
    static String overCap(Path output) {
        if (output == null) {
            return null;
        }
        long[] bytes = {0}, entries = {0};
        try {
            Files.walkFileTree(output, EnumSet.noneOf(FileVisitOption.class), DEPTH, new SimpleFileVisitor<>() {
                @Override
                public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attributes) {
                    return ++entries[0] > ENTRIES_CAP ? FileVisitResult.TERMINATE : FileVisitResult.CONTINUE;
                }

                @Override
                public FileVisitResult visitFile(Path file, BasicFileAttributes attributes) {
                    bytes[0] += attributes.isRegularFile() ? attributes.size() : 0;
                    return ++entries[0] > ENTRIES_CAP || bytes[0] > BYTES_CAP ? FileVisitResult.TERMINATE
                            : FileVisitResult.CONTINUE;
                }

                @Override
                public FileVisitResult visitFileFailed(Path file, IOException e) {
                    return FileVisitResult.CONTINUE;   // gone meanwhile, or beyond a path's length
                }
            });
        } catch (IOException | RuntimeException e) {
            return null;
        }
        if (bytes[0] > BYTES_CAP) {
            return "the program was stopped: it wrote more than " + Sandbox.size(BYTES_CAP) + " to its output folder";
        }
        return entries[0] > ENTRIES_CAP ? "the program was stopped: it made more than " + ENTRIES_CAP
                + " files and folders in its output folder" : null;
    }
}
