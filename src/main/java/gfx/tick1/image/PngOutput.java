package gfx.tick1.image;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * Writes PNG files so that a failure never leaves a half-written image: the PNG goes to a
 * temporary file beside the target and is renamed over it only once complete. A rename within
 * one directory is atomic on POSIX file systems, so readers see the old file or the new one.
 */
public final class PngOutput {

    private PngOutput() {
    }

    /** Writes {@code image} to {@code target}, replacing it only when the whole PNG is on disk. */
    public static void write(BufferedImage image, Path target) throws IOException {
        Path absolute = target.toAbsolutePath();
        Path directory = absolute.getParent();
        if (Files.isDirectory(absolute)) {
            throw new IOException("is a directory, expected a file name for the PNG");
        }
        if (directory == null || !Files.isDirectory(directory)) {
            throw new IOException("directory " + directory + " does not exist");
        }
        Path temporary = Files.createTempFile(directory, "." + absolute.getFileName() + ".", ".tmp");
        try {
            try (OutputStream out = Files.newOutputStream(temporary)) {
                write(image, out);
            }
            try {
                Files.move(temporary, absolute, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temporary, absolute, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /** Encodes {@code image} as PNG onto a stream (standard output, for {@code --output -}). */
    public static void write(BufferedImage image, OutputStream out) throws IOException {
        PngEncoder.write(image, out);
        out.flush();
    }
}
