package gfx.tick1.image;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.SinglePixelPackedSampleModel;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.zip.Adler32;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

/**
 * A PNG encoder for 8-bit RGB images, several times faster than ImageIO's at the same standard
 * format: any PNG reader decodes the file to exactly the image's pixels.
 *
 * <p>ImageIO tries five filters on every row and deflates on one thread; at 3840 x 2160 that
 * took as long as rendering the frame. Here every row uses the Sub filter (each byte minus the
 * one three to its left, PNG specification section 9.2), which turns the smooth shading of a
 * ray-traced image into small numbers, and bands of rows are deflated at the fastest level in
 * parallel, as pigz does: each band but the last ends with a sync flush, so the bands' raw
 * deflate data joins into one valid stream, and their Adler-32 checksums are combined.
 */
public final class PngEncoder {

    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    /** Rows per band: large enough that deflate finds its matches, small enough to share out. */
    private static final int BAND_ROWS = 64;
    private static final int MAX_CHUNK = 1 << 20;
    private static final int FILTER_SUB = 1;

    private PngEncoder() {
    }

    /** Writes {@code image} as PNG: fastest compression, all cores. */
    public static void write(BufferedImage image, OutputStream out) throws IOException {
        write(image, out, Deflater.BEST_SPEED);
    }

    /** Writes {@code image} as PNG with the given deflate level (0 to 9, or Deflater.HUFFMAN_ONLY). */
    public static void write(BufferedImage image, OutputStream out, int level) throws IOException {
        int width = image.getWidth(), height = image.getHeight();
        int[] pixels = packedPixels(image);
        int bands = (height + BAND_ROWS - 1) / BAND_ROWS;
        List<Band> compressed = IntStream.range(0, bands).parallel()
                .mapToObj(band -> compress(pixels, width, height, band, bands, level))
                .collect(Collectors.toList());

        ByteArrayOutputStream idat = new ByteArrayOutputStream();
        // zlib header: deflate with a 32 KiB window (0x78), and a check value making it divisible by 31.
        idat.write(0x78);
        idat.write(0x01);
        long adler = 1;
        for (Band band : compressed) {
            idat.write(band.deflated);
            adler = combineAdler32(adler, band.adler, band.length);
        }
        writeInt(idat, (int) adler);

        DataOutputStream png = new DataOutputStream(out);
        png.write(SIGNATURE);
        ByteArrayOutputStream header = new ByteArrayOutputStream();
        writeInt(header, width);
        writeInt(header, height);
        header.write(new byte[] {8, 2, 0, 0, 0}); // 8 bits a channel, RGB, deflate, adaptive filters, no interlace
        chunk(png, "IHDR", header.toByteArray(), 0, header.size());
        byte[] data = idat.toByteArray();
        for (int offset = 0; offset < data.length; offset += MAX_CHUNK) {
            chunk(png, "IDAT", data, offset, Math.min(MAX_CHUNK, data.length - offset));
        }
        chunk(png, "IEND", new byte[0], 0, 0);
        png.flush();
    }

    /** One band of rows, filtered and deflated, with the Adler-32 of its filtered bytes. */
    private record Band(byte[] deflated, long adler, long length) {
    }

    private static Band compress(int[] pixels, int width, int height, int band, int bands, int level) {
        int fromRow = band * BAND_ROWS, toRow = Math.min(height, fromRow + BAND_ROWS);
        int rowBytes = 1 + 3 * width;
        byte[] filtered = new byte[rowBytes * (toRow - fromRow)];
        int at = 0;
        for (int y = fromRow; y < toRow; y++) {
            filtered[at++] = FILTER_SUB;
            int left = 0; // the Sub filter's byte to the left of the first pixel is 0
            for (int x = 0, i = y * width; x < width; x++, i++) {
                int rgb = pixels[i];
                filtered[at++] = (byte) ((rgb >> 16) - (left >> 16));
                filtered[at++] = (byte) ((rgb >> 8) - (left >> 8));
                filtered[at++] = (byte) (rgb - left);
                left = rgb;
            }
        }
        Adler32 adler = new Adler32();
        adler.update(filtered);
        Deflater deflater = new Deflater(level == Deflater.HUFFMAN_ONLY ? Deflater.DEFAULT_COMPRESSION : level, true);
        if (level == Deflater.HUFFMAN_ONLY) {
            deflater.setStrategy(Deflater.HUFFMAN_ONLY);
        }
        deflater.setInput(filtered);
        // All bands but the last end on a byte boundary without the final-block bit, so they join.
        boolean last = band == bands - 1;
        if (last) {
            deflater.finish();
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream(filtered.length / 4 + 64);
        byte[] buffer = new byte[1 << 16];
        while (true) {
            int n = last ? deflater.deflate(buffer) : deflater.deflate(buffer, 0, buffer.length, Deflater.SYNC_FLUSH);
            out.write(buffer, 0, n);
            if (last ? deflater.finished() : n < buffer.length && deflater.needsInput()) {
                break;
            }
        }
        deflater.end();
        return new Band(out.toByteArray(), adler.getValue(), filtered.length);
    }

    /**
     * The Adler-32 of two byte strings joined, from theirs and the second's length n2. Adler-32
     * keeps A = 1 + sum of bytes and B = sum of the running A's (mod 65521); continuing from
     * (A1, B1) adds the second string's bytes to A and adds A1 - 1 more to each of its n2
     * running sums, so A = A1 + A2 - 1 and B = B1 + B2 + n2 (A1 - 1).
     */
    static long combineAdler32(long first, long second, long secondLength) {
        final long modulus = 65521;
        long a1 = first & 0xFFFF, b1 = first >>> 16, a2 = second & 0xFFFF, b2 = second >>> 16;
        long a = Math.floorMod(a1 + a2 - 1, modulus);
        long b = Math.floorMod(b1 + b2 + (secondLength % modulus) * (a1 - 1), modulus);
        return b << 16 | a;
    }

    private static int[] packedPixels(BufferedImage image) {
        if (image.getType() == BufferedImage.TYPE_INT_RGB && image.getRaster().getDataBuffer() instanceof DataBufferInt data
                && image.getSampleModel() instanceof SinglePixelPackedSampleModel model
                && model.getScanlineStride() == image.getWidth() && data.getOffset() == 0
                && image.getRaster().getSampleModelTranslateX() == 0 && image.getRaster().getSampleModelTranslateY() == 0) {
            return data.getData();
        }
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private static void chunk(DataOutputStream out, String type, byte[] data, int offset, int length) throws IOException {
        byte[] name = type.getBytes(StandardCharsets.US_ASCII);
        CRC32 crc = new CRC32();
        crc.update(name);
        crc.update(data, offset, length);
        out.writeInt(length);
        out.write(name);
        out.write(data, offset, length);
        out.writeInt((int) crc.getValue());
    }

    private static void writeInt(OutputStream out, int value) throws IOException {
        out.write(value >>> 24);
        out.write(value >>> 16);
        out.write(value >>> 8);
        out.write(value);
    }
}
