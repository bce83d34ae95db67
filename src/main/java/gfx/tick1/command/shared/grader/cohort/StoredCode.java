package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.grader.lookalike.ComparedCode;
import gfx.tick1.command.shared.grader.lookalike.ParsedCode;
import gfx.tick1.command.shared.grader.lookalike.ParsedCodes;
import gfx.tick1.command.shared.grader.sandbox.Leftovers;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.engine.io.OwnFolder;
import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Objects;
import java.util.Properties;
import java.util.UUID;

/**
 * The code the look-alike check parsed, kept in a folder of the result store ({@link ResultStore#PARSED}), one
 * file a digest, so that a cohort graded again parses only the files it has not parsed before. Each file is named
 * by the digest together with this build of tick1's: a new build parses again. A file is written whole and then
 * renamed into place; one that cannot be read is no code, and the files are parsed again.
 */
final class StoredCode implements ParsedCodes {

    /** The prefix of files being written, before the id of the process writing them, as in {@link ResultStore}. */
    private static final String WRITING = ".writing-";

    private final Path folder;
    private final String build;

    /** The store in {@code folder}, made if need be; what a stopped run left half-written is deleted. */
    StoredCode(Path folder, String build) throws IOException {
        this.folder = OwnFolder.at(folder);
        this.build = build;
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(folder, WRITING + "*")) {
            for (Path entry : entries) {
                if (Leftovers.leftByAGoneRun(entry.getFileName().toString().substring(WRITING.length()))) {
                    WorkFolder.delete(entry);
                }
            }
        }
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
            return new ParsedCode(members, notes);
        } catch (IOException | RuntimeException e) {
            return null;   // damaged, unreadable or not this program's: parsed again
        }
    }

    @Override
    public void put(String digest, ParsedCode code) {
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
        Path writing = folder.resolve(WRITING + Leftovers.mark() + UUID.randomUUID());
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

    /** The file of the code with {@code digest}, as this build parsed it. */
    private Path fileOf(String digest) {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            sha.update((build + "\n" + digest).getBytes(StandardCharsets.UTF_8));
            return folder.resolve(HexFormat.of().formatHex(sha.digest()));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }
}
