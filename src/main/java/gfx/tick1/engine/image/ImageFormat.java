package gfx.tick1.engine.image;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The image formats a user may hand tick1 in place of a PNG, known by the first bytes of a file
 * (their magic numbers) and by the extensions of a file name. tick1 reads and writes PNG only:
 * it is lossless, so every pixel of a render survives exactly; JPEG's compression changes pixels.
 */
public enum ImageFormat {
    PNG("PNG", new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}, "png"),
    JPEG("JPEG", new byte[] {(byte) 0xFF, (byte) 0xD8, (byte) 0xFF}, "jpg", "jpeg", "jpe", "jfif"),
    GIF("GIF", "GIF8".getBytes(StandardCharsets.ISO_8859_1), "gif"),
    BMP("BMP", "BM".getBytes(StandardCharsets.ISO_8859_1), "bmp"),
    TIFF_LITTLE_ENDIAN("TIFF", new byte[] {'I', 'I', '*', 0}, "tif", "tiff"),
    TIFF_BIG_ENDIAN("TIFF", new byte[] {'M', 'M', 0, '*'}),
    // "RIFF", a 4-byte length, then "WEBP"; a '?' of a magic number matches any byte.
    WEBP("WebP", "RIFF????WEBP".getBytes(StandardCharsets.ISO_8859_1), "webp");

    /** The bytes of a file's start that {@link #of(byte[])} needs. */
    public static final int SIGNATURE_LENGTH = 12;

    private final String title;
    private final byte[] magic;
    private final List<String> extensions;

    ImageFormat(String title, byte[] magic, String... extensions) {
        this.title = title;
        this.magic = magic;
        this.extensions = List.of(extensions);
    }

    /** The format whose magic number the bytes start with. */
    public static Optional<ImageFormat> of(byte[] start) {
        return Arrays.stream(values()).filter(format -> format.startsWith(start)).findFirst();
    }

    /** The format a file name's extension names (".JPG" too), if it names one. */
    public static Optional<ImageFormat> ofName(String name) {
        int dot = name.lastIndexOf('.');
        String extension = dot < 0 ? "" : name.substring(dot + 1).toLowerCase(Locale.ROOT);
        return Arrays.stream(values()).filter(format -> format.extensions.contains(extension)).findFirst();
    }

    /** The name with its extension made .png: "out.jpg" becomes "out.png". */
    public static String asPng(String name) {
        int dot = name.lastIndexOf('.');
        return (dot < 0 ? name : name.substring(0, dot)) + ".png";
    }

    private boolean startsWith(byte[] start) {
        if (start.length < magic.length) {
            return false;
        }
        for (int i = 0; i < magic.length; i++) {
            if (magic[i] != '?' && start[i] != magic[i]) {
                return false;
            }
        }
        return true;
    }

    /** Why a file of this format (not PNG) is not read or written: for a message after the file's name. */
    public String notPng() {
        return this == JPEG ? "a JPEG image, not a PNG: JPEG's compression changes pixels, so it cannot match a "
                + "render pixel for pixel; save the image as PNG" : "a " + title + " image, not a PNG; save it as PNG";
    }
}
