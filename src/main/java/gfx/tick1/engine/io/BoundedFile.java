package gfx.tick1.engine.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A file read whole, but never past a bound. A file named on the command line may be a device ({@code /dev/zero},
 * {@code /dev/urandom}) or a stream that never ends: its size says nothing (0, or none), and reading it to its
 * end never ends, or ends when Java runs out of memory. So a file that tick1 reads whole is read here: at most one
 * byte past the bound, and refused beyond it with {@link TooLarge}, whose message says how large a file may be.
 */
public final class BoundedFile {

    private static final long MIB = 1024 * 1024;

    private BoundedFile() {
    }

    /** A file past the bound: its message is the reason ("larger than 1 MiB"), without the file's name. */
    public static final class TooLarge extends IOException {
        private static final long serialVersionUID = 1L;

        private final long size;
        private final long bound;

        TooLarge(long size, long bound) {
            super("larger than " + BoundedFile.size(bound));
            this.size = size;
            this.bound = bound;
        }

        /** The file's size, for a regular file whose size said it was too large; -1 for a device or a stream. */
        public long size() {
            return size;
        }

        /** The most bytes that the file may have. */
        public long bound() {
            return bound;
        }
    }

    /**
     * The bytes of {@code file}, at most {@code bound} of them.
     *
     * @throws TooLarge    when the file has more (a regular file is measured first, and not read at all)
     * @throws IOException when it cannot be read
     */
    public static byte[] read(Path file, long bound) throws IOException {
        if (bound < 0 || bound >= Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("a bound of " + bound + " bytes cannot be held in one array");
        }
        if (Files.isRegularFile(file) && Files.size(file) > bound) {
            throw new TooLarge(Files.size(file), bound);
        }
        try (InputStream in = Files.newInputStream(file)) {
            byte[] bytes = in.readNBytes((int) bound + 1);
            if (bytes.length > bound) {
                throw new TooLarge(-1, bound);
            }
            return bytes;
        }
    }

    /** A size for messages: "64 MiB", or bytes when not a whole number of MiB. */
    public static String size(long bytes) {
        return bytes % MIB == 0 && bytes > 0 ? bytes / MIB + " MiB" : bytes + " bytes";
    }
}
