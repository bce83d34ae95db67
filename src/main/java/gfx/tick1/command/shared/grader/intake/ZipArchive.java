package gfx.tick1.command.shared.grader.intake;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.channels.SeekableByteChannel;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.zip.ZipEntry;
import org.apache.commons.compress.archivers.zip.ZipArchiveEntry;
import org.apache.commons.compress.archivers.zip.ZipFile;

/**
 * A zip read from its central directory by Commons Compress, with tick1's policy on top: anything hostile is refused
 * before a byte of content is inflated, and an entry's content is counted against a cap as it inflates.
 *
 * <p>Refused, with one line naming the entry: a name that is not UTF-8, absolute, or climbs out with {@code ..}
 * (zip slip), two entries of one name, a symbolic link (a Unix mode in the central directory, which
 * {@code java.util.zip} does not expose), more entries than the limit, an encrypted entry or one neither stored nor
 * deflated, and a local header naming another file than the central directory does: {@code ZipInputStream} and the
 * tools built on it see only the local headers, so such a zip shows staff one file while tick1 grades another.
 */
final class ZipArchive {

    private static final int LOCAL_SIZE = 30;

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
    record Entry(String name, boolean directory, ZipArchiveEntry zipEntry) {
    }

    private final SeekableByteChannel channel;
    private final ZipFile zip;
    private final List<Entry> entries;

    private ZipArchive(SeekableByteChannel channel, ZipFile zip, List<Entry> entries) {
        this.channel = channel;
        this.zip = zip;
        this.entries = entries;
    }

    /** The entries, in the central directory's order. */
    List<Entry> entries() {
        return entries;
    }

    /**
     * Reads the central directory of the zip on {@code channel} (a file's, or a {@code SeekableInMemoryByteChannel}),
     * refusing a hostile or unreadable zip. The channel stays open for {@link #read}; its owner closes it.
     */
    static ZipArchive open(SeekableByteChannel channel, int maxEntries) throws IOException {
        long size = channel.size();   // asked first: Commons Compress closes the channel of a zip it refuses
        ZipFile zip;
        try {
            // Names are decoded here, from the raw bytes; Unicode extra fields could give another name.
            zip = ZipFile.builder().setSeekableByteChannel(channel).setUseUnicodeExtraFields(false).get();
        } catch (IOException e) {
            Throwable cause = e;   // Commons Compress wraps what went wrong in a message about the channel
            while (cause.getCause() != null) {
                cause = cause.getCause();
            }
            throw new Refused(size < 22 ? "not a zip (too short)"
                    : String.valueOf(cause.getMessage()).contains("not a ZIP archive")
                            ? "not a zip (no end of central directory)"
                            : "the zip's central directory is damaged (" + cause.getMessage() + ")");
        }
        List<ZipArchiveEntry> all = Collections.list(zip.getEntries());   // in the central directory's order
        if (all.size() > maxEntries) {
            throw new Refused("the zip has " + all.size() + " entries, more than the limit of " + maxEntries);
        }
        List<Entry> entries = new ArrayList<>(all.size());
        Set<String> names = new HashSet<>();
        for (ZipArchiveEntry entry : all) {
            String name = checkedName(entry.getRawName());
            if (entry.isUnixSymlink()) {
                throw new Refused("entry " + name + " is a symbolic link, which tick1 does not follow");
            }
            boolean isDirectory = name.endsWith("/");
            String bare = isDirectory ? name.substring(0, name.length() - 1) : name;
            if (!names.add(bare)) {
                throw new Refused("two entries are named " + bare + "; tick1 cannot tell which is meant");
            }
            entries.add(new Entry(bare, isDirectory, entry));
        }
        return new ZipArchive(channel, zip, List.copyOf(entries));
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
        ZipArchiveEntry zipEntry = entry.zipEntry();
        if (zipEntry.getGeneralPurposeBit().usesEncryption()) {
            throw new Refused("entry " + entry.name() + " is encrypted");
        }
        int method = zipEntry.getMethod();
        if (method != ZipEntry.STORED && method != ZipEntry.DEFLATED || !zip.canReadEntryData(zipEntry)) {
            throw new Refused("entry " + entry.name() + " is compressed with method " + method
                    + "; tick1 reads stored and deflated entries");
        }
        checkLocalName(entry);
        byte[] content;
        try (InputStream in = zip.getInputStream(zipEntry)) {
            content = upTo(in, cap, entry);
        } catch (TooLarge | Refused e) {
            throw e;
        } catch (IOException | RuntimeException e) {
            throw new Refused("entry " + entry.name() + " is damaged (" + e.getMessage() + ")");
        }
        if (content.length != zipEntry.getSize()) {
            throw new Refused("entry " + entry.name() + " is damaged (its size is not the one recorded)");
        }
        return content;
    }

    /** The entry's name in its local header must be the central directory's, byte for byte. */
    private void checkLocalName(Entry entry) throws IOException {
        byte[] central = entry.zipEntry().getRawName();
        ByteBuffer local = ByteBuffer.allocate(LOCAL_SIZE + central.length);
        synchronized (channel) {   // Commons Compress reads the same channel, and also under its lock
            channel.position(entry.zipEntry().getLocalHeaderOffset());
            while (local.hasRemaining() && channel.read(local) >= 0) {
                continue;
            }
        }
        byte[] header = local.array();
        int nameLength = (header[26] & 0xFF) | (header[27] & 0xFF) << 8;
        if (local.hasRemaining() || nameLength != central.length
                || !Arrays.equals(header, LOCAL_SIZE, header.length, central, 0, central.length)) {
            throw new Refused("entry " + entry.name() + " has another name in its local header; the zip's two "
                    + "directories disagree");
        }
    }

    /** Reads {@code in} to its end, counting the bytes as they come: nothing beyond {@code cap} is inflated. */
    private static byte[] upTo(InputStream in, long cap, Entry entry) throws IOException {
        byte[] bytes = in.readNBytes((int) Math.min(cap, Integer.MAX_VALUE - 8));   // reads in small chunks
        if (bytes.length == cap && in.read() >= 0) {
            throw new TooLarge(entry.name() + " is larger than " + IntakeLimits.size(cap));
        }
        return bytes;
    }
}
