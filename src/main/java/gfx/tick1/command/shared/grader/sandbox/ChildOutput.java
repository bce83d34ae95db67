package gfx.tick1.command.shared.grader.sandbox;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Arrays;
import javax.imageio.ImageIO;

/**
 * Reads what the student's process left in its output folder, as a hostile party wrote it: only
 * regular files (never through a link, never a FIFO or device that could block the read), only up
 * to a size cap, and text with its control characters taken out, so that nothing the student
 * printed can move the cursor or overwrite a line of the report. It is read only after the
 * sandbox has ended, so that no process of the student's can swap a file while it is read.
 */
public final class ChildOutput {

    /** The most text read from one file of the child's. */
    static final int TEXT_CAP = 64 * 1024;
    /** The cap on the probes' log: the answers to every random input, with room to spare. */
    static final int PROBES_CAP = 1 << 20;

    /** The eight bytes that begin every PNG file. */
    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

    private ChildOutput() {
    }

    /** Why a file could not be used, in words for the report. */
    static final class Unusable extends Exception {
        private static final long serialVersionUID = 1L;

        Unusable(String reason) {
            super(reason);
        }
    }

    /** Whether {@code file} is there as a regular file (a link, even to a regular file, is not). */
    public static boolean isRegularFile(Path file) {
        try {
            return Files.readAttributes(file, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS).isRegularFile();
        } catch (IOException e) {
            return false;
        }
    }

    /** Whether {@code folder} is there as a folder, not a link to one. */
    static boolean isDirectory(Path folder) {
        try {
            return Files.readAttributes(folder, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS).isDirectory();
        } catch (IOException e) {
            return false;
        }
    }

    /**
     * Copies the folders and regular files under {@code from} to {@code to}, and nothing else:
     * no link is followed or copied.
     */
    static void copy(Path from, Path to) throws IOException {
        try (var files = Files.walk(from)) {
            for (Path file : files.toList()) {
                Path copy = to.resolve(from.relativize(file).toString());
                if (isDirectory(file)) {
                    Files.createDirectories(copy);
                } else if (isRegularFile(file)) {
                    Files.copy(file, copy, LinkOption.NOFOLLOW_LINKS);
                }
            }
        }
    }

    /** At most {@code cap} bytes of the regular file {@code file}, or null when it is not one or cannot be read. */
    static byte[] read(Path file, int cap) throws IOException {
        if (!isRegularFile(file)) {
            return null;
        }
        try (InputStream in = Files.newInputStream(file, LinkOption.NOFOLLOW_LINKS)) {
            return in.readNBytes(cap);
        } catch (NoSuchFileException | AccessDeniedException e) {
            // Removed meanwhile, or made unreadable (chmod 000) by the code: when the grader is not
            // root, it is the student's failure that the file is not there to read, never the grader's.
            return null;
        }
    }

    /** The text of the regular file {@code file}, capped and made printable, or null when it is not one. */
    static String readText(Path file) throws IOException {
        return readText(file, TEXT_CAP);
    }

    /** As {@link #readText(Path)}, with at most {@code cap} bytes read. */
    static String readText(Path file, int cap) throws IOException {
        byte[] bytes = read(file, cap);
        return bytes == null ? null : printable(new String(bytes, StandardCharsets.UTF_8));
    }

    /**
     * The PNG image in {@code file}, which must be {@code width} x {@code height}: the size is read
     * from the header before anything is decoded, and the file may not be larger than an
     * uncompressed image of that size could be.
     */
    static BufferedImage readPng(Path file, int width, int height) throws IOException, Unusable {
        if (!isRegularFile(file)) {
            throw new Unusable("the image file is not a regular file");
        }
        // Stored (uncompressed) deflate blocks, filter bytes and chunk headers add a little to the raw 4 bytes a pixel.
        long cap = 4L * width * height + 5L * height + 64 * 1024;
        byte[] bytes = read(file, (int) Math.min(Integer.MAX_VALUE - 16, cap + 1));
        if (bytes == null) {
            throw new Unusable("the image file is not readable");
        }
        // The signature, then the IHDR chunk: length (4), "IHDR" (4), width (4), height (4).
        if (bytes.length < 24 || !Arrays.equals(bytes, 0, 8, PNG_SIGNATURE, 0, 8)
                || !new String(bytes, 12, 4, StandardCharsets.ISO_8859_1).equals("IHDR")) {
            throw new Unusable("the image file is not a PNG");
        }
        long pngWidth = ByteBuffer.wrap(bytes, 16, 4).getInt() & 0xFFFFFFFFL;
        long pngHeight = ByteBuffer.wrap(bytes, 20, 4).getInt() & 0xFFFFFFFFL;
        if (pngWidth != width || pngHeight != height) {
            throw new Unusable("the image is " + pngWidth + " x " + pngHeight + ", expected " + width + " x " + height);
        }
        if (bytes.length > cap) {
            throw new Unusable("the image file is larger than any " + width + " x " + height + " PNG");
        }
        BufferedImage image;
        try {
            image = ImageIO.read(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            image = null;
        }
        if (image == null || image.getWidth() != width || image.getHeight() != height) {
            throw new Unusable("the image file is not a readable PNG");
        }
        return image;
    }

    /**
     * {@code text} with every control character but the newline taken out (a tab becomes a
     * space), and with the Unicode characters that reorder or hide text (bidirectional controls,
     * zero-width characters): what is left prints as itself and cannot rewrite a line.
     */
    public static String printable(String text) {
        StringBuilder clean = new StringBuilder(text.length());
        text.codePoints().forEach(c -> {
            if (c == '\n') {
                clean.append('\n');
            } else if (c == '\t') {
                clean.append(' ');
            } else if (!Character.isISOControl(c) && !hidesOrReorders(c)) {
                clean.appendCodePoint(c);
            }
        });
        return clean.toString();
    }

    private static boolean hidesOrReorders(int c) {
        int type = Character.getType(c);
        return type == Character.FORMAT || type == Character.PRIVATE_USE || type == Character.SURROGATE
                || type == Character.UNASSIGNED || c == 0x2028 || c == 0x2029;
    }
}
