package gfx.tick1.engine.image;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The file a run finds where it is to write its image: what a refused or failed run must leave
 * exactly as it was. Its bytes are no PNG, and hold a newline, a zero and a high byte, so that a
 * partial write or a copy through text would show.
 */
public final class EarlierImage {

    private static final byte[] BYTES = "an earlier image\n\u0000\u00ff".getBytes(StandardCharsets.ISO_8859_1);

    private EarlierImage() {
    }

    /** Writes the earlier image to {@code file}, and returns the file. */
    public static Path writeTo(Path file) throws IOException {
        Files.write(file, BYTES);
        return file;
    }

    /** The earlier image's bytes, to compare a file with. */
    public static byte[] bytes() {
        return BYTES.clone();
    }
}
