package gfx.tick1.command.shared.grader.cohort;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Enforcement;
import gfx.tick1.command.shared.grader.sandbox.Leftovers;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.io.OwnFolder;
import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Objects;
import java.util.Properties;
import java.util.UUID;
import java.util.stream.Stream;

/**
 * The cohort grade's memory: each finished result, stored the moment it is known, so that a grade
 * that is stopped (Ctrl-C, a crash, a power cut) loses nothing and a second run grades only what
 * is new or changed. A result lives in a folder of its own, named by its {@link #key}: its fields
 * in {@code result.properties} and the images of its failing scenes beside them. The folder is
 * written under a temporary name, flushed to disk, then renamed into place in one step: a folder
 * with a key's name is always complete, and a half-written one is never read (and is deleted at
 * the next start).
 */
public final class ResultStore {

    /** What is stored in each result's folder besides the images. */
    private static final String RESULT_FILE = "result.properties";
    /**
     * The prefix of folders being written, before the id of the process writing them: never read, and deleted by
     * the next start once that process is gone (two runs may write into one report folder at once).
     */
    private static final String WRITING = ".writing-";
    /**
     * Changes when the way a result is stored or keyed changes, so that older results are graded again
     * (2: what the grade found is stored beside its words; 3: the sandbox's rules are part of the key; 4: a
     * pass's tested facts are stored apart from its notes on what the scenes do not test, and reasons are a
     * sentence a finding).
     */
    private static final String FORMAT = "tick1 grade result 4";

    private final Path folder;

    /**
     * The store in {@code folder}, made if need be (never a link: one there is replaced, {@link OwnFolder}); what a
     * stopped run left half-written is deleted, and what a live run is writing is left to it.
     */
    public ResultStore(Path folder) throws IOException {
        this.folder = OwnFolder.at(folder);
        deleteHalfWritten(folder);
    }

    /** Deletes what stopped runs left half-written in {@code folder}, leaving what a live run is writing. */
    static void deleteHalfWritten(Path folder) throws IOException {
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(folder, WRITING + "*")) {
            for (Path entry : entries) {
                if (Leftovers.leftByAGoneRun(entry.getFileName().toString().substring(WRITING.length()))) {
                    WorkFolder.delete(entry);
                }
            }
        }
    }

    /**
     * The key of a submission's result: SHA-256 of the store's format, this program's version, build
     * ({@link #build}) and Java's, the options that change a grade, what the sandbox held the code to
     * ({@code --no-sandbox} or not, and what this machine let it enforce: code can pass under weaker rules
     * and fail under stronger ones), every grading scene's name and bytes, and the two files' names (they appear in
     * messages) and bytes. Each part is preceded by its length, so that no two different inputs make
     * the same bytes.
     */
    static String key(Submission submission, Grading grading, Enforcement enforcement) throws IOException {
        return key(submission, grading, enforcement, ThisBuild.DIGEST);
    }

    /** {@link #key(Submission, Grading, Enforcement)}, with {@code build} the digest of tick1's code. */
    static String key(Submission submission, Grading grading, Enforcement enforcement, String build)
            throws IOException {
        MessageDigest sha = sha256();
        // tick1's jar names its version in its manifest, for every package of the jar.
        String version = ResultStore.class.getPackage().getImplementationVersion();
        Grading.Limits limits = grading.limits();
        add(sha, FORMAT);
        add(sha, "tick1 " + (version == null ? "(development build)" : version) + " build " + build);
        add(sha, "Java " + System.getProperty("java.version"));
        add(sha, limits.width() + "x" + limits.height() + " " + limits.timeLimit().toMillis() + " ms "
                + limits.memoryMegabytes() + " MiB reference " + limits.referenceChoice());
        add(sha, !enforcement.confined() ? "no sandbox" : "sandbox" + (enforcement.ownUser() ? ", own user" : "")
                + (enforcement.totals() ? ", control group" : "")
                + (enforcement.reservationsRefused() ? ", reservations refused" : "")
                + (enforcement.ownDisks() ? ", tmpfs output" : ""));
        for (Grading.CourseScene scene : grading.scenes()) {
            add(sha, scene.name() + (scene.hidden() ? " hidden" : " public"));
            add(sha, Files.readAllBytes(scene.file()));
        }
        for (Submission.SourceFile file : submission.files()) {
            add(sha, file.path());
            add(sha, file.content());
        }
        return HexFormat.of().formatHex(sha.digest());
    }

    /**
     * The digest of tick1's code at {@code code}, its jar or the folder of its classes: a new build of one version
     * changes it, and its results are graded again. Unreadable, it is a fresh one each run: nothing is reused.
     */
    static String build(Path code) {
        try (Stream<Path> files = Files.walk(code)) {
            MessageDigest sha = sha256();
            for (Path file : files.filter(Files::isRegularFile).sorted().toList()) {
                add(sha, code.relativize(file).toString());
                add(sha, Files.readAllBytes(file));
            }
            return HexFormat.of().formatHex(sha.digest());
        } catch (IOException | RuntimeException e) {
            return "unread " + UUID.randomUUID();
        }
    }

    static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }

    static void add(MessageDigest sha, String text) {
        add(sha, text.getBytes(StandardCharsets.UTF_8));
    }

    private static void add(MessageDigest sha, byte[] bytes) {
        sha.update(ByteBuffer.allocate(Long.BYTES).putLong(bytes.length).array());
        sha.update(bytes);
    }

    /** The folder of the stored result with {@code key}: its images are there. */
    Path folderOf(String key) {
        return folder.resolve(key);
    }

    /** The stored result with {@code key}, as the result of {@code submission}, or null when there is none. */
    StudentResult load(String key, Submission submission) throws IOException {
        Path file = folderOf(key).resolve(RESULT_FILE);
        // A result read through a link could be anyone's: it is no result.
        if (!Files.isDirectory(folderOf(key), LinkOption.NOFOLLOW_LINKS)
                || !Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS)) {
            return null;
        }
        Properties p = new Properties();
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(in);
        } catch (CharacterCodingException | AccessDeniedException | IllegalArgumentException e) {
            // damaged (bytes that are not UTF-8, a malformed escape), or not readable: no result, and the
            // submission is graded again
            return null;
        }
        try {
            List<SceneResult> scenes = new ArrayList<>();
            int count = Integer.parseInt(p.getProperty("scenes"));
            for (int i = 0; i < count; i++) {
                String at = "scene." + i + ".";
                String explanation = p.getProperty(at + "explanation");
                scenes.add(new SceneResult(p.getProperty(at + "name"),
                        Boolean.parseBoolean(p.getProperty(at + "hidden")),
                        Boolean.parseBoolean(p.getProperty(at + "passed")),
                        explanation.isEmpty() ? List.of() : explanation.lines().toList(),
                        new SceneResult.Images(orNull(p.getProperty(at + "heatMap")),
                        orNull(p.getProperty(at + "yours")), orNull(p.getProperty(at + "expected")))));
            }
            return new StudentResult(submission,
                    new StudentResult.Summary(Boolean.parseBoolean(p.getProperty("passed")),
                    Integer.parseInt(p.getProperty("scenesPassed")), Integer.parseInt(p.getProperty("scenesTotal")),
                    category(p), p.getProperty("reason")), scenes,
                    Duration.ofNanos(Long.parseLong(p.getProperty("timeNanos"))), findings(p));
        } catch (RuntimeException e) {
            return null;   // not a result this program wrote: grade again
        }
    }

    /** A new folder to write a result's images into before {@link #save} stores it. */
    Path newEntry() throws IOException {
        return Files.createDirectory(writingName());
    }

    /** Why {@code entry} takes no file now, in the file system's words (full, read-only, gone). */
    static String refusal(Path entry) {
        try {
            Files.delete(Files.createTempFile(entry, ".probe-", ""));
            return "its images could not be written there";
        } catch (IOException e) {
            return IoErrors.reason(e);
        }
    }

    /** A new name for a folder being written, which carries this process's mark. */
    private Path writingName() {
        return writingName(folder);
    }

    /** A new name in {@code folder} for a file or folder being written, which carries this process's mark. */
    static Path writingName(Path folder) {
        return folder.resolve(WRITING + Leftovers.mark() + UUID.randomUUID());
    }

    /**
     * Stores {@code result} under {@code key}, with the images already written into {@code entry}
     * (from {@link #newEntry}), and deletes {@code entry}: on return the result is on disk.
     */
    void save(String key, StudentResult result, Path entry) throws IOException {
        Properties p = new Properties();
        p.setProperty("passed", Boolean.toString(result.passed()));
        p.setProperty("scenesPassed", Integer.toString(result.scenesPassed()));
        p.setProperty("scenesTotal", Integer.toString(result.scenesTotal()));
        p.setProperty("diagnosis", result.diagnosis().label());
        p.setProperty("outcome", result.diagnosis() instanceof Category.Outcome outcome ? outcome.name() : "");
        p.setProperty("reason", result.reason());
        p.setProperty("timeNanos", Long.toString(result.time().toNanos()));
        p.setProperty("scenes", Integer.toString(result.scenes().size()));
        for (int i = 0; i < result.scenes().size(); i++) {
            SceneResult scene = result.scenes().get(i);
            String at = "scene." + i + ".";
            p.setProperty(at + "name", scene.name());
            p.setProperty(at + "hidden", Boolean.toString(scene.hidden()));
            p.setProperty(at + "passed", Boolean.toString(scene.passed()));
            p.setProperty(at + "explanation", String.join("\n", scene.explanation()));
            p.setProperty(at + "heatMap", orEmpty(scene.files().heatMap()));
            p.setProperty(at + "yours", orEmpty(scene.files().yours()));
            p.setProperty(at + "expected", orEmpty(scene.files().expected()));
        }
        Findings found = result.findings();
        p.setProperty("findings.catalogued", found.catalogued() == null ? "" : found.catalogued().name());
        setList(p, "findings.failed", found.failed());
        setList(p, "findings.notes", found.notes());
        setList(p, "findings.figures", found.figures());
        setList(p, "findings.reread", found.reread());
        try (Writer out = Files.newBufferedWriter(entry.resolve(RESULT_FILE), StandardCharsets.UTF_8)) {
            p.store(out, null);
        }
        try (DirectoryStream<Path> files = Files.newDirectoryStream(entry)) {
            for (Path file : files) {
                force(file);
            }
        }
        force(entry);
        if (Files.exists(folderOf(key), LinkOption.NOFOLLOW_LINKS)
                && !Files.isDirectory(folderOf(key), LinkOption.NOFOLLOW_LINKS)) {
            // A link or a file where a result's folder goes (load never reads through a link): itself, not what a
            // link names, deleted; a folder another job stored there meanwhile is not deleted, and is met below.
            try {
                Files.deleteIfExists(folderOf(key));
            } catch (DirectoryNotEmptyException e) {
                // another job's result
            }
        }
        try {
            Files.move(entry, folderOf(key), StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException e) {
            if (!Files.isDirectory(folderOf(key), LinkOption.NOFOLLOW_LINKS)) {
                throw e;
            }
            if (load(key, result.submission()) != null) {
                // The same files graded by another job meanwhile: that result stands.
                WorkFolder.delete(entry);
            } else {
                // A damaged result, no result: renamed as being written (a stop leaves it to the next start), then
                // deleted, so that this one takes its place.
                Path damaged = Files.move(folderOf(key), writingName(), StandardCopyOption.ATOMIC_MOVE);
                WorkFolder.delete(damaged);
                Files.move(entry, folderOf(key), StandardCopyOption.ATOMIC_MOVE);
            }
        }
        force(folder);
    }

    /** A stored result's category: an outcome by its name, else a mistake by its label. */
    private static Category category(Properties p) {
        String outcome = p.getProperty("outcome");
        return outcome.isEmpty() ? new Category.Mistake(Objects.requireNonNull(p.getProperty("diagnosis")))
                : Category.Outcome.valueOf(outcome);
    }

    /** What a stored result's grade found; an unknown catalogue entry throws, and the result is graded again. */
    private static Findings findings(Properties p) {
        String catalogued = p.getProperty("findings.catalogued");
        return new Findings(catalogued.isEmpty() ? null : Variant.valueOf(catalogued), list(p, "findings.failed"),
                list(p, "findings.notes"), list(p, "findings.figures"), list(p, "findings.reread"));
    }

    private static void setList(Properties p, String name, List<String> values) {
        p.setProperty(name, Integer.toString(values.size()));
        for (int i = 0; i < values.size(); i++) {
            p.setProperty(name + "." + i, values.get(i));
        }
    }

    private static List<String> list(Properties p, String name) {
        List<String> values = new ArrayList<>();
        int count = Integer.parseInt(p.getProperty(name));
        for (int i = 0; i < count; i++) {
            values.add(Objects.requireNonNull(p.getProperty(name + "." + i)));
        }
        return values;
    }

    /** Flushes a file or folder to the disk, so that a power cut after the rename finds it whole. */
    private static void force(Path path) {
        try (FileChannel channel = FileChannel.open(path, StandardOpenOption.READ)) {
            channel.force(true);
        } catch (IOException e) {
            // Not every file system can flush a folder: the rename is still all or nothing.
        }
    }

    private static String orNull(String value) {
        return value == null || value.isEmpty() ? null : value;
    }

    private static String orEmpty(String value) {
        return value == null ? "" : value;
    }
}
