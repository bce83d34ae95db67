package gfx.tick1.engine.image;

import gfx.tick1.engine.io.BoundedFile;
import gfx.tick1.engine.io.IoErrors;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;

/** Reads an image file for comparison, turning every way it can fail into one readable line. */
public final class PngInput {

    /** The most bytes an image file may have: far more than a PNG of any render a course asks for. */
    public static final long MAX_BYTES = 64L * 1024 * 1024;

    private PngInput() {
    }

    /**
     * The image in {@code file}; any failure is an IOException whose message names the file. The
     * file must be a PNG by its bytes, whatever its name: another format (a JPEG above all, whose
     * pixels its compression has changed) is refused, never compared as if it were a render.
     */
    public static BufferedImage read(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new IOException(file + ": is a directory, expected a PNG file");
        }
        byte[] bytes;
        try {
            // Read whole but bounded, as a scene is: the file may be a device or a pipe that never ends.
            bytes = BoundedFile.read(file, MAX_BYTES);
        } catch (BoundedFile.TooLarge e) {
            throw new IOException(file + ": " + e.getMessage() + ", expected a PNG image");
        } catch (IOException e) {
            throw new IOException(file + ": " + IoErrors.reason(e));
        }
        ImageFormat format = ImageFormat.of(Arrays.copyOf(bytes, Math.min(bytes.length,
                ImageFormat.SIGNATURE_LENGTH))).orElse(null);
        if (format != ImageFormat.PNG) {
            throw new IOException(file + ": " + (format == null ? "not a PNG image" : format.notPng()));
        }
        BufferedImage image;
        try {
            image = ImageIO.read(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            // ImageIO reports a damaged PNG as IIOException, and some as runtime exceptions.
            throw new IOException(file + ": not a readable PNG image (" + e.getMessage() + ")");
        }
        if (image == null) {
            throw new IOException(file + ": not a readable PNG image");
        }
        return image;
    }
}
