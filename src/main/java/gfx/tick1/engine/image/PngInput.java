package gfx.tick1.engine.image;

import gfx.tick1.engine.io.IoErrors;
import java.awt.image.BufferedImage;
import java.io.BufferedInputStream;
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

    /** A file that is not a PNG, known by its first bytes: its message is already complete. */
    private static final class NotAPng extends IOException {
        private static final long serialVersionUID = 1L;

        NotAPng(String message) {
            super(message);
        }
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
        BufferedImage image;
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file))) {
            in.mark(ImageFormat.SIGNATURE_LENGTH);
            ImageFormat format = ImageFormat.of(in.readNBytes(ImageFormat.SIGNATURE_LENGTH)).orElse(null);
            in.reset();
            if (format != ImageFormat.PNG) {
                throw new NotAPng(file + ": " + (format == null ? "not a PNG image" : format.notPng()));
            }
            image = ImageIO.read(in);
        } catch (NotAPng e) {
            throw e;
        } catch (NoSuchFileException | AccessDeniedException e) {
            throw new IOException(file + ": " + IoErrors.reason(e));
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
