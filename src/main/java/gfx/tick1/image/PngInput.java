package gfx.tick1.image;

import gfx.tick1.io.IoErrors;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/** Reads an image file for comparison, turning every way it can fail into one readable line. */
public final class PngInput {

    private PngInput() {
    }

    /** The image in {@code file}; any failure is an IOException whose message names the file. */
    public static BufferedImage read(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new IOException(file + ": is a directory, expected a PNG file");
        }
        BufferedImage image;
        try (InputStream in = Files.newInputStream(file)) {
            image = ImageIO.read(in);
        } catch (NoSuchFileException | AccessDeniedException e) {
            throw new IOException(file + ": " + IoErrors.reason(e));
        } catch (IOException | RuntimeException e) {
            // ImageIO reports a damaged PNG as IIOException, and some as runtime exceptions.
            throw new IOException(file + ": not a readable PNG image (" + e.getMessage() + ")");
        }
        if (image == null) {
            throw new IOException(file + ": not a PNG image (or another format Java can read)");
        }
        return image;
    }
}
