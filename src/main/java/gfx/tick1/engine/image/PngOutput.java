package gfx.tick1.engine.image;

import gfx.tick1.engine.io.AtomicFile;
import gfx.tick1.engine.io.IoErrors;
import java.awt.image.BufferedImage;
import java.awt.image.RenderedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import javax.imageio.IIOException;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * Writes PNG files through javax.imageio's PNG writer, so that a failure never leaves a
 * half-written image: the PNG goes to a temporary file beside the target and is renamed over it
 * only once complete ({@link AtomicFile}). A rename within one directory is atomic on POSIX file systems, so readers
 * see the old file or the new one.
 *
 * <p>If the write fails (a full disk, say) the temporary file is deleted and the exception
 * passed on. If the JVM is stopped meanwhile (Ctrl-C, SIGTERM, System.exit) a shutdown hook
 * deletes it. Only a hard kill (SIGKILL, power loss) can leave one behind: a hidden file named
 * {@code .NAME.png.RANDOM.tmp}, never the target itself.
 */
public final class PngOutput {

    /** Encodes an image onto a stream; tests substitute one that fails part way. */
    @FunctionalInterface
    interface Encoder {
        void encode(BufferedImage image, OutputStream out) throws IOException;
    }

    /**
     * The deflate level tick1 writes with: the quickest of ImageIO's levels for files not much
     * larger than its default's (docs/benchmark.md, "PNG encoding of one frame").
     */
    public static final int DEFLATE_LEVEL = 2;

    private PngOutput() {
    }

    /** Writes {@code image} to {@code target}, replacing it only when the whole PNG is on disk. */
    public static void write(BufferedImage image, Path target) throws IOException {
        write(image, target, PngOutput::write);
    }

    static void write(BufferedImage image, Path target, Encoder encoder) throws IOException {
        write(target, out -> encoder.encode(image, out));
    }

    /**
     * Writes a PNG already encoded ({@link #write(RenderedImage, OutputStream)} into memory) to
     * {@code target}, as whole as {@link #write(BufferedImage, Path)} writes one.
     */
    public static void write(byte[] png, Path target) throws IOException {
        write(target, out -> out.write(png));
    }

    private static void write(Path target, AtomicFile.Content contents) throws IOException {
        Path given = target.toAbsolutePath();
        if (Files.isDirectory(given)) {
            throw new IOException("is a directory, expected a file name for the PNG");
        }
        if (Files.exists(given) && !Files.isRegularFile(given)) {
            // A device or a pipe (/dev/stdout, a FIFO): renaming a file over it would replace it,
            // and there is nothing to keep whole, so the PNG is written straight into it. Asked of
            // the path as given, which the operating system follows to what it names: the links of
            // /dev/stdout lead to /proc/self/fd/1 and on to a name such as "pipe:[1234]", which is
            // no path at all.
            try (OutputStream out = Files.newOutputStream(given)) {
                contents.writeTo(out);
            }
            return;
        }
        Path absolute = followLinks(given);
        Path directory = absolute.getParent();
        if (directory == null || !Files.exists(directory)) {
            throw new IOException("directory " + directory + " does not exist");
        }
        if (!Files.isDirectory(directory)) {
            throw new IOException(directory + " is not a directory");
        }
        AtomicFile.write(absolute, contents, e -> cannotCreate(directory, e));
    }

    /** Most failures to create a file name only the file; say the reason where one is known. */
    private static IOException cannotCreate(Path directory, IOException e) {
        if (!(e instanceof FileSystemException)) {
            return e;
        }
        boolean known = e instanceof AccessDeniedException || ((FileSystemException) e).getReason() != null;
        return new IOException("cannot create a file in " + directory + (known ? " (" + IoErrors.reason(e) + ")" : ""));
    }

    /**
     * The file a path names once symbolic links are followed, so that the finished image replaces
     * the file a link points to, not the link. A link to a file not yet there is followed too.
     */
    private static Path followLinks(Path path) throws IOException {
        for (int hops = 0; hops < 40 && Files.isSymbolicLink(path); hops++) {
            path = path.resolveSibling(Files.readSymbolicLink(path)).toAbsolutePath().normalize();
        }
        return path;
    }

    /**
     * Encodes {@code image} as PNG onto a stream (standard output, for {@code --output -}) through
     * ImageIO's own PNG writer. The stream is flushed, not closed.
     */
    public static void write(RenderedImage image, OutputStream out) throws IOException {
        write(image, out, DEFLATE_LEVEL);
    }

    /**
     * Loads ImageIO's registry and its PNG writer, so that a write started later (on another
     * thread, say, while the image is still being drawn) does not wait for them; and what the
     * temporary file beside the target needs (its name's random part, its permissions), which
     * is most of the time a small PNG takes to be written.
     */
    public static void load() {
        ImageIO.getImageWritersByFormatName("png").next().dispose();
        new SecureRandom().nextLong();
        PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-rw-rw-"));
    }

    /** As {@link #write(BufferedImage, OutputStream)}, at a deflate level from 0 (none) to 9 (best). */
    public static void write(RenderedImage image, OutputStream out, int deflateLevel) throws IOException {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("png").next();
        ImageWriteParam param = writer.getDefaultWriteParam();
        param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
        // ImageIO's PNG writer takes a "quality" q from 0 to 1 and deflates at level 9 - round(9 q).
        param.setCompressionQuality((9 - deflateLevel) / 9f);
        // A memory cache, not ImageIO's default of a cache file in java.io.tmpdir: nothing is
        // written anywhere but the destination, and a full /tmp cannot fail the write.
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.write(null, new IIOImage(image, null, null), param);
        } catch (IIOException e) {
            throw rootCause(e);
        } finally {
            writer.dispose();
        }
        out.flush();
    }

    /**
     * ImageIO reports a failed write ("No space left on device", a closed pipe) as "I/O error
     * writing PNG file!" with the real reason as its cause; the reason is what a user needs.
     */
    private static IOException rootCause(IIOException e) {
        Throwable cause = e;
        while (cause.getCause() instanceof IOException deeper) {
            cause = deeper;
        }
        return (IOException) cause;
    }
}
