package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.lookalike.ComparedCode;
import gfx.tick1.command.shared.grader.lookalike.ParsedCode;
import gfx.tick1.command.shared.grader.lookalike.ParsedCodes;
import gfx.tick1.engine.io.OwnFolder;
import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Objects;
import java.util.Properties;

/**
 * The code the look-alike check parsed, kept in a folder of the result store ({@link #FOLDER}), one
 * file a digest, so that a cohort graded again parses only the files it has not parsed before. Each file is named
 * by the digest together with this build of tick1's: a new build parses again. A file is written whole and then
 * renamed into place; one that cannot be read, or whose sum of what it holds and of its digest is not the one it
 * holds (a file cut short by a stop, a full disk or a copy), is no code, and the files are parsed again.
 */
public final class StoredCode implements ParsedCodes {

    /** The folder in the result store where the code is kept. */
    public static final String FOLDER = "parsed";

    /**
     * The most characters of code a file keeps: five times two files at the look-alike check's cap on what it
     * parses. Honest code prints at about its own length; only nesting prints longer (its indent grows as the square
     * of its depth), and such code is parsed again each run rather than fill the report folder.
     */
    static final int MOST_CHARACTERS = 2_000_000;

    private final Path folder;
    private final String build;

    /**
     * The code kept in the result store in {@code store}, for this build; none is kept when its folder cannot be made
     * (a full or read-only report folder), and every file is parsed.
     */
    public static ParsedCodes in(Path store) {
        try {
            return new StoredCode(store.resolve(FOLDER), ThisBuild.DIGEST);
        } catch (IOException e) {
            return ParsedCodes.NONE;
        }
    }

    /** The store in {@code folder}, made if need be; what a stopped run left half-written is deleted. */
    StoredCode(Path folder, String build) throws IOException {
        this.folder = OwnFolder.at(folder);
        this.build = build;
        ResultStore.deleteHalfWritten(folder);
    }

    @Override
    public ParsedCode get(String digest) {
        Path file = fileOf(digest);
        if (!Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS)) {
            return null;
        }
        Properties p = new Properties();
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(in);
            List<ComparedCode.Member> members = new ArrayList<>();
            int count = Integer.parseInt(p.getProperty("members"));
            for (int i = 0; i < count; i++) {
                String at = "member." + i + ".";
                members.add(new ComparedCode.Member(Objects.requireNonNull(p.getProperty(at + "file")),
                        Objects.requireNonNull(p.getProperty(at + "signature")),
                        Objects.requireNonNull(p.getProperty(at + "text"))));
            }
            List<String> notes = new ArrayList<>();
            int noted = Integer.parseInt(p.getProperty("notes"));
            for (int i = 0; i < noted; i++) {
                notes.add(Objects.requireNonNull(p.getProperty("note." + i)));
            }
            ParsedCode code = new ParsedCode(members, notes);
            // A file cut short may end in a whole line that holds part of a value, or miss a count's digit.
            return sum(digest, code).equals(p.getProperty("sum")) ? code : null;
        } catch (IOException | RuntimeException e) {
            return null;   // damaged, unreadable or not this program's: parsed again
        }
    }

    @Override
    public void put(String digest, ParsedCode code) {
        long characters = code.notes().stream().mapToLong(String::length).sum() + code.members().stream()
                .mapToLong(member -> member.file().length() + member.signature().length() + member.text().length())
                .sum();
        if (characters > MOST_CHARACTERS) {
            return;
        }
        Properties p = new Properties();
        p.setProperty("members", Integer.toString(code.members().size()));
        for (int i = 0; i < code.members().size(); i++) {
            ComparedCode.Member member = code.members().get(i);
            String at = "member." + i + ".";
            p.setProperty(at + "file", member.file());
            p.setProperty(at + "signature", member.signature());
            p.setProperty(at + "text", member.text());
        }
        p.setProperty("notes", Integer.toString(code.notes().size()));
        for (int i = 0; i < code.notes().size(); i++) {
            p.setProperty("note." + i, code.notes().get(i));
        }
        p.setProperty("sum", sum(digest, code));
        Path writing = ResultStore.writingName(folder);
        try {
            try (Writer out = Files.newBufferedWriter(writing, StandardCharsets.UTF_8)) {
                p.store(out, null);
            }
            Files.move(writing, fileOf(digest), StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException e) {
            // Not kept (a full or read-only report folder): the files are parsed again next time.
            try {
                Files.deleteIfExists(writing);
            } catch (IOException again) {
                // left to the next start, which deletes it
            }
        }
    }

    /** SHA-256 of {@code digest} and of every part of {@code code}, each preceded by its length. */
    private static String sum(String digest, ParsedCode code) {
        MessageDigest sha = ResultStore.sha256();
        ResultStore.add(sha, digest);
        ResultStore.add(sha, Integer.toString(code.members().size()));
        for (ComparedCode.Member member : code.members()) {
            ResultStore.add(sha, member.file());
            ResultStore.add(sha, member.signature());
            ResultStore.add(sha, member.text());
        }
        ResultStore.add(sha, Integer.toString(code.notes().size()));
        for (String note : code.notes()) {
            ResultStore.add(sha, note);
        }
        return HexFormat.of().formatHex(sha.digest());
    }

    /** The file of the code with {@code digest}, as this build parsed it. */
    private Path fileOf(String digest) {
        MessageDigest sha = ResultStore.sha256();
        sha.update((build + "\n" + digest).getBytes(StandardCharsets.UTF_8));
        return folder.resolve(HexFormat.of().formatHex(sha.digest()));
    }
}
