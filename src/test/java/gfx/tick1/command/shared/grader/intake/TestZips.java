package gfx.tick1.command.shared.grader.intake;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;
import java.util.zip.Deflater;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

/** Zips built in memory for the intake's tests: ordinary ones through ZipOutputStream, hostile ones byte by byte. */
final class TestZips {

    private TestZips() {
    }

    /** An ordinary zip of these entries, in order; a name ending in / is a folder. */
    static byte[] zip(Map<String, byte[]> entries) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ZipOutputStream zip = new ZipOutputStream(bytes, StandardCharsets.UTF_8)) {
            for (Map.Entry<String, byte[]> entry : entries.entrySet()) {
                zip.putNextEntry(new ZipEntry(entry.getKey()));
                zip.write(entry.getValue());
                zip.closeEntry();
            }
        }
        return bytes.toByteArray();
    }

    /** Entries in order, for {@link #zip(Map)}: name, content, name, content... */
    static Map<String, byte[]> entries(Object... nameThenContent) {
        Map<String, byte[]> entries = new LinkedHashMap<>();
        for (int i = 0; i < nameThenContent.length; i += 2) {
            Object content = nameThenContent[i + 1];
            entries.put((String) nameThenContent[i],
                    content instanceof byte[] ? (byte[]) content : ((String) content).getBytes(StandardCharsets.UTF_8));
        }
        return entries;
    }

    /** A zip written byte by byte (APPNOTE.TXT 4.3), so that it can be everything ZipOutputStream refuses to write. */
    static final class Raw {
        private final List<byte[]> locals = new ArrayList<>();
        private final List<byte[]> centrals = new ArrayList<>();
        private int offset;

        /** A stored entry with a UTF-8 name. */
        Raw add(String name, String content) {
            byte[] bytes = content.getBytes(StandardCharsets.UTF_8);
            byte[] rawName = name.getBytes(StandardCharsets.UTF_8);
            return add(rawName, rawName, bytes, false, bytes.length, 0, 0);
        }

        /** A stored symbolic link made on Unix, pointing at {@code target}. */
        Raw symlink(String name, String target) {
            byte[] rawName = name.getBytes(StandardCharsets.UTF_8);
            byte[] bytes = target.getBytes(StandardCharsets.UTF_8);
            return add(rawName, rawName, bytes, false, bytes.length, 3, 0120777L << 16);
        }

        /**
         * Any entry.
         *
         * @param centralName the name in the central directory
         * @param localName   the name in the local header
         * @param deflate     deflate the content, else store it
         * @param claimedSize the uncompressed size written in the headers
         * @param host        the "version made by" host (3 is Unix)
         * @param external    the external attributes (a Unix mode in the upper 16 bits)
         */
        Raw add(byte[] centralName, byte[] localName, byte[] content, boolean deflate, long claimedSize, int host,
                long external) {
            byte[] data = deflate ? deflate(content) : content;
            CRC32 crc = new CRC32();
            crc.update(content);
            ByteBuffer local = little(30 + localName.length + data.length);
            local.putInt(0x04034b50).putShort((short) 20).putShort((short) 0).putShort((short) (deflate ? 8 : 0))
                    .putInt(0).putInt((int) crc.getValue()).putInt(data.length).putInt((int) claimedSize)
                    .putShort((short) localName.length).putShort((short) 0).put(localName).put(data);
            ByteBuffer central = little(46 + centralName.length);
            central.putInt(0x02014b50).putShort((short) (host << 8 | 20)).putShort((short) 20).putShort((short) 0)
                    .putShort((short) (deflate ? 8 : 0)).putInt(0).putInt((int) crc.getValue()).putInt(data.length)
                    .putInt((int) claimedSize).putShort((short) centralName.length).putShort((short) 0)
                    .putShort((short) 0).putShort((short) 0).putShort((short) 0).putInt((int) external)
                    .putInt(offset).put(centralName);
            locals.add(local.array());
            centrals.add(central.array());
            offset += local.capacity();
            return this;
        }

        byte[] bytes() {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            locals.forEach(out::writeBytes);
            int directorySize = 0;
            for (byte[] central : centrals) {
                out.writeBytes(central);
                directorySize += central.length;
            }
            ByteBuffer end = little(22);
            end.putInt(0x06054b50).putShort((short) 0).putShort((short) 0).putShort((short) centrals.size())
                    .putShort((short) centrals.size()).putInt(directorySize).putInt(offset).putShort((short) 0);
            out.writeBytes(end.array());
            return out.toByteArray();
        }

        private static ByteBuffer little(int size) {
            return ByteBuffer.allocate(size).order(ByteOrder.LITTLE_ENDIAN);
        }

        private static byte[] deflate(byte[] content) {
            Deflater deflater = new Deflater(Deflater.BEST_COMPRESSION, true);
            deflater.setInput(content);
            deflater.finish();
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            byte[] buffer = new byte[64 * 1024];
            while (!deflater.finished()) {
                out.write(buffer, 0, deflater.deflate(buffer));
            }
            deflater.end();
            return out.toByteArray();
        }
    }
}
