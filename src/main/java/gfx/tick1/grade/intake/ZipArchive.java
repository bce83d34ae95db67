package gfx.tick1.grade.intake;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;

/**
 * A zip read from its central directory, in memory, refusing anything hostile before a byte of content is inflated.
 *
 * <p>Why not {@code java.util.zip.ZipFile} or {@code ZipInputStream} alone: a symbolic link is marked only in the
 * central directory's external attributes, which neither exposes; {@code ZipFile} needs the zip on disk (a zip inside
 * a student's folder must stay in memory) and fails on a name that is not UTF-8 without saying which;
 * {@code ZipInputStream} sees only the local headers, which a crafted zip can make disagree with the central
 * directory that every unzip tool lists. So the directory is read here (APPNOTE.TXT, sections 4.3.7 to 4.3.16) and
 * each local header is checked against it before its data is read; {@link Inflater} does the decompression, with
 * the output counted as it is produced and its size checked against the directory's at the end. (The CRC-32 is not
 * checked: the grader takes a file's bytes as they are, and tick1's sources compute no checksum by hand.)
 *
 * <p>Refused, with one line naming the entry: a name that is not UTF-8, absolute, or climbs out with {@code ..}
 * (zip slip), two entries of one name, a symbolic link, more entries than the limit, a split or zip64 archive.
 */
final class ZipArchive {

    private static final int END_SIGNATURE = 0x06054b50;
    private static final int ZIP64_LOCATOR_SIGNATURE = 0x07064b50;
    private static final int CENTRAL_SIGNATURE = 0x02014b50;
    private static final int LOCAL_SIGNATURE = 0x04034b50;
    private static final int END_SIZE = 22;
    private static final int CENTRAL_SIZE = 46;
    private static final int LOCAL_SIZE = 30;
    private static final int MAX_COMMENT = 0xFFFF;
    private static final int UNIX_HOST = 3;
    private static final int FILE_TYPE_MASK = 0xF000;
    private static final int SYMLINK_TYPE = 0xA000;
    private static final int STORED = 0;
    private static final int DEFLATED = 8;
    private static final int ENCRYPTED_FLAG = 1;
    private static final int CHUNK = 64 * 1024;
    /** 65,535 entries with long names fit in a few MiB; more is no zip tick1 needs to read. */
    private static final long MAX_DIRECTORY = 64L * 1024 * 1024;

    /** Random access to the zip's bytes: a file on disk or a zip held in memory. */
    interface Source {
        long size() throws IOException;

        /** Reads exactly {@code length} bytes at {@code position}, or fails. */
        void read(long position, byte[] into, int offset, int length) throws IOException;

        static Source of(FileChannel channel) {
            return new Source() {
                @Override
                public long size() throws IOException {
                    return channel.size();
                }

                @Override
                public void read(long position, byte[] into, int offset, int length) throws IOException {
                    ByteBuffer buffer = ByteBuffer.wrap(into, offset, length);
                    while (buffer.hasRemaining()) {
                        if (channel.read(buffer, position + buffer.position() - offset) < 0) {
                            throw new Refused("the zip is truncated");
                        }
                    }
                }
            };
        }

        static Source of(byte[] bytes) {
            return new Source() {
                @Override
                public long size() {
                    return bytes.length;
                }

                @Override
                public void read(long position, byte[] into, int offset, int length) throws IOException {
                    if (position < 0 || position + length > bytes.length) {
                        throw new Refused("the zip is truncated");
                    }
                    System.arraycopy(bytes, (int) position, into, offset, length);
                }
            };
        }
    }

    /** Why a zip, or one of its entries, cannot be used: one line, without the zip's own name. */
    static final class Refused extends IOException {
        private static final long serialVersionUID = 1L;

        Refused(String message) {
            super(message);
        }
    }

    /** An entry's content is larger than the caller's cap; nothing beyond the cap was inflated. */
    static final class TooLarge extends IOException {
        private static final long serialVersionUID = 1L;

        TooLarge(String message) {
            super(message);
        }
    }

    /**
     * One entry of the central directory.
     *
     * @param name      its name, with {@code \} read as {@code /} and no trailing {@code /}
     * @param directory a folder entry (the name ended in {@code /})
     */
    record Entry(String name, boolean directory, int method, int flags, long compressedSize, long size,
            long localOffset, byte[] rawName) {
    }

    private final Source source;
    private final List<Entry> entries;

    private ZipArchive(Source source, List<Entry> entries) {
        this.source = source;
        this.entries = entries;
    }

    /** The entries, in the central directory's order. */
    List<Entry> entries() {
        return entries;
    }

    /** Reads the central directory, refusing a hostile or unreadable zip. */
    static ZipArchive open(Source source, int maxEntries) throws IOException {
        long size = source.size();
        long end = findEnd(source, size);
        byte[] record = new byte[END_SIZE];
        source.read(end, record, 0, END_SIZE);
        int disk = u16(record, 4);
        int directoryDisk = u16(record, 6);
        int count = u16(record, 10);
        long directorySize = u32(record, 12);
        long directoryOffset = u32(record, 16);
        if (disk != 0 || directoryDisk != 0 || count != u16(record, 8)) {
            throw new Refused("the zip is split across several files, which tick1 does not read");
        }
        if (end >= 20 && u32(read(source, end - 20, 4), 0) == ZIP64_LOCATOR_SIGNATURE
                || count == 0xFFFF || directoryOffset == 0xFFFFFFFFL) {
            throw new Refused("the zip is a zip64 archive (over 4 GiB or 65,535 entries), which tick1 does not read");
        }
        if (count > maxEntries) {
            throw new Refused("the zip has " + count + " entries, more than the limit of " + maxEntries);
        }
        if (directorySize > MAX_DIRECTORY) {
            throw new Refused("the zip's central directory is larger than " + IntakeLimits.size(MAX_DIRECTORY));
        }
        if (directoryOffset + directorySize > end) {
            throw new Refused("the zip's central directory lies outside the file");
        }
        byte[] directory = read(source, directoryOffset, (int) directorySize);
        return new ZipArchive(source, readDirectory(directory, count));
    }

    private static List<Entry> readDirectory(byte[] directory, int count) throws Refused {
        List<Entry> entries = new ArrayList<>(count);
        Set<String> names = new HashSet<>();
        int at = 0;
        for (int i = 0; i < count; i++) {
            if (at + CENTRAL_SIZE > directory.length || u32(directory, at) != CENTRAL_SIGNATURE) {
                throw new Refused("the zip's central directory is damaged");
            }
            int madeBy = u16(directory, at + 4) >> 8;
            int nameLength = u16(directory, at + 28);
            int next = at + CENTRAL_SIZE + nameLength + u16(directory, at + 30) + u16(directory, at + 32);
            if (next > directory.length) {
                throw new Refused("the zip's central directory is damaged");
            }
            byte[] rawName = Arrays.copyOfRange(directory, at + CENTRAL_SIZE, at + CENTRAL_SIZE + nameLength);
            String name = checkedName(rawName);
            int mode = (int) (u32(directory, at + 38) >>> 16);
            if (madeBy == UNIX_HOST && (mode & FILE_TYPE_MASK) == SYMLINK_TYPE) {
                throw new Refused("entry " + name + " is a symbolic link, which tick1 does not follow");
            }
            boolean isDirectory = name.endsWith("/");
            String bare = isDirectory ? name.substring(0, name.length() - 1) : name;
            if (!names.add(bare)) {
                throw new Refused("two entries are named " + bare + "; tick1 cannot tell which is meant");
            }
            entries.add(new Entry(bare, isDirectory, u16(directory, at + 10), u16(directory, at + 8),
                    u32(directory, at + 20), u32(directory, at + 24), u32(directory, at + 42), rawName));
            at = next;
        }
        return List.copyOf(entries);
    }

    /** The name as UTF-8, with {@code \} as {@code /}; refused when it is not UTF-8, absolute or climbs out. */
    private static String checkedName(byte[] raw) throws Refused {
        String name;
        try {
            name = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(raw)).toString();
        } catch (CharacterCodingException e) {
            String shown = new String(raw, StandardCharsets.ISO_8859_1).replaceAll("[^\\x20-\\x7e]", "?");
            throw new Refused("entry " + shown + " has a name that is not UTF-8");
        }
        name = name.replace('\\', '/');
        String shown = name.replaceAll("\\p{Cntrl}", "?");
        if (name.isEmpty() || name.indexOf('\0') >= 0) {
            throw new Refused("an entry has an empty name or one with a NUL character");
        }
        if (name.startsWith("/") || name.matches("^[A-Za-z]:.*")) {
            throw new Refused("entry " + shown + " has an absolute name (zip slip)");
        }
        for (String part : name.split("/")) {
            if (part.equals("..")) {
                throw new Refused("entry " + shown + " climbs out of the folder with .. (zip slip)");
            }
        }
        return name.equals(shown) ? name : shown;
    }

    /**
     * The entry's content, inflated into memory; {@link TooLarge} once it would exceed {@code cap} bytes, however
     * small the header says it is.
     */
    byte[] read(Entry entry, long cap) throws IOException {
        if ((entry.flags() & ENCRYPTED_FLAG) != 0) {
            throw new Refused("entry " + entry.name() + " is encrypted");
        }
        if (entry.method() != STORED && entry.method() != DEFLATED) {
            throw new Refused("entry " + entry.name() + " is compressed with method " + entry.method()
                    + "; tick1 reads stored and deflated entries");
        }
        byte[] local = read(source, entry.localOffset(), LOCAL_SIZE);
        if (u32(local, 0) != LOCAL_SIGNATURE) {
            throw new Refused("entry " + entry.name() + " has no local header where the directory says");
        }
        int nameLength = u16(local, 26);
        byte[] localName = read(source, entry.localOffset() + LOCAL_SIZE, nameLength);
        if (!Arrays.equals(localName, entry.rawName())) {
            throw new Refused("entry " + entry.name() + " has another name in its local header; the zip's two "
                    + "directories disagree");
        }
        long start = entry.localOffset() + LOCAL_SIZE + nameLength + u16(local, 28);
        if (start + entry.compressedSize() > source.size()) {
            throw new Refused("entry " + entry.name() + " runs past the end of the zip");
        }
        byte[] content = entry.method() == STORED ? stored(entry, start, cap) : inflated(entry, start, cap);
        if (content.length != entry.size()) {
            throw new Refused("entry " + entry.name() + " is damaged (its size is not the one recorded)");
        }
        return content;
    }

    private byte[] stored(Entry entry, long start, long cap) throws IOException {
        if (entry.compressedSize() > cap) {
            throw tooLarge(entry, cap);
        }
        return read(source, start, (int) entry.compressedSize());
    }

    private byte[] inflated(Entry entry, long start, long cap) throws IOException {
        Inflater inflater = new Inflater(true);
        try {
            Output output = new Output(cap, entry);
            byte[] input = new byte[CHUNK];
            byte[] buffer = new byte[CHUNK];
            long position = start;
            long left = entry.compressedSize();
            boolean padded = false;
            while (!inflater.finished()) {
                if (inflater.needsInput()) {
                    if (left > 0) {
                        int n = (int) Math.min(CHUNK, left);
                        source.read(position, input, 0, n);
                        inflater.setInput(input, 0, n);
                        position += n;
                        left -= n;
                    } else if (!padded) {
                        // A raw deflate stream may need one byte past its end to finish (Inflater's "nowrap").
                        inflater.setInput(new byte[1]);
                        padded = true;
                    } else {
                        throw new Refused("entry " + entry.name() + " is damaged (its data ends early)");
                    }
                }
                int n = inflater.inflate(buffer);
                if (n == 0 && inflater.needsDictionary()) {
                    throw new Refused("entry " + entry.name() + " is damaged (it asks for a dictionary)");
                }
                output.write(buffer, n);
            }
            return output.bytes();
        } catch (DataFormatException e) {
            throw new Refused("entry " + entry.name() + " is damaged (" + e.getMessage() + ")");
        } finally {
            inflater.end();
        }
    }

    /** Inflated bytes, counted as they come. */
    private static final class Output {
        private final long cap;
        private final Entry entry;
        private byte[] bytes = new byte[CHUNK];
        private int length;

        Output(long cap, Entry entry) {
            this.cap = cap;
            this.entry = entry;
        }

        void write(byte[] buffer, int n) throws TooLarge {
            if (length + (long) n > cap) {
                throw tooLarge(entry, cap);
            }
            if (length + n > bytes.length) {
                bytes = Arrays.copyOf(bytes, (int) Math.min(cap, Math.max(2L * bytes.length, length + n)));
            }
            System.arraycopy(buffer, 0, bytes, length, n);
            length += n;
        }

        byte[] bytes() {
            return Arrays.copyOf(bytes, length);
        }
    }

    private static TooLarge tooLarge(Entry entry, long cap) {
        return new TooLarge(entry.name() + " is larger than " + IntakeLimits.size(cap));
    }

    private static long findEnd(Source source, long size) throws IOException {
        if (size < END_SIZE) {
            throw new Refused("not a zip (too short)");
        }
        int tail = (int) Math.min(size, END_SIZE + MAX_COMMENT);
        byte[] bytes = read(source, size - tail, tail);
        for (int at = tail - END_SIZE; at >= 0; at--) {
            if (u32(bytes, at) == END_SIGNATURE && at + END_SIZE + u16(bytes, at + 20) == tail) {
                return size - tail + at;
            }
        }
        throw new Refused("not a zip (no end of central directory)");
    }

    private static byte[] read(Source source, long position, int length) throws IOException {
        byte[] bytes = new byte[length];
        source.read(position, bytes, 0, length);
        return bytes;
    }

    private static int u16(byte[] b, int at) {
        return (b[at] & 0xFF) | (b[at + 1] & 0xFF) << 8;
    }

    private static long u32(byte[] b, int at) {
        return (u16(b, at) | (long) u16(b, at + 2) << 16) & 0xFFFFFFFFL;
    }
}
