package gfx.tick1.command.shared.grader.intake;

import gfx.tick1.command.shared.grader.model.CohortInputException;
import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.SeekableByteChannel;
import java.nio.file.DirectoryStream;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import org.apache.commons.compress.utils.SeekableInMemoryByteChannel;

/**
 * The intake: a cohort's download from Moodle (the "Download all submissions" zip, or the folder it unpacks to) read
 * into one {@link Submission} per student, sorted by folder name.
 *
 * <p>Nothing is written to disk and nothing is unpacked: only the two files the tick asks for, and any zip inside a
 * student's folder, are read into memory, within {@link IntakeLimits}. Links are never followed.
 *
 * <p>Where a problem lies decides what it costs. The download itself is staff's: a download that is unreadable, not
 * a zip, or hostile (zip slip, a symbolic link, a name that is not UTF-8, two entries of one name, a damaged entry,
 * too many entries, too many bytes inflated in all) is refused as a whole with a {@link CohortInputException}. What
 * a student put in their folder is theirs: a missing file, two candidates for one, an empty folder, a file over the
 * size limit, a link, or a hostile or unreadable zip of their own make that student's submission a problem, which
 * the grader reports as a failure with the reason.
 */
public final class Submissions {

    private static final String SPHERE = "Sphere.java";
    private static final String RENDERER = "Renderer.java";
    /** Where macOS's archiver keeps resource forks: never a student. */
    private static final String MAC_RESOURCES = "__MACOSX";

    private final Path download;
    private final IntakeLimits limits;
    private long inflated;

    private Submissions(Path download, IntakeLimits limits) {
        this.download = download;
        this.limits = limits;
    }

    /** Reads a cohort's download within the default limits. */
    public static List<Submission> read(Path path) throws IOException {
        return read(path, IntakeLimits.DEFAULT);
    }

    /**
     * Reads a cohort's download: one submission per top-level folder, sorted by folder name.
     *
     * @throws CohortInputException the download as a whole cannot be used; the message is one line naming it
     */
    public static List<Submission> read(Path path, IntakeLimits limits) throws IOException {
        Submissions intake = new Submissions(path, limits);
        if (Files.isDirectory(path)) {
            try {
                return intake.resolveAll(intake.readFolder(path));
            } catch (CohortInputException e) {
                throw e;
            } catch (IOException e) {
                throw new CohortInputException(path + ": cannot read the folder (" + reason(e) + ")");
            }
        }
        if (!Files.isRegularFile(path)) {
            throw new CohortInputException(path + ": no such file or folder");
        }
        Optional<String> notZip = FileKind.unlessZip(path);
        if (notZip.isPresent()) {
            throw new CohortInputException(path + ": " + notZip.get() + ", not a zip: --submissions wants Moodle's "
                    + "\"Download all submissions\" zip, or the folder it unpacks to (a grading worksheet goes to "
                    + "--worksheet)");
        }
        // The zip's entries are read while its channel is open: the submissions are resolved inside.
        try (FileChannel channel = FileChannel.open(path, StandardOpenOption.READ)) {
            return intake.resolveAll(intake.readZip(path, channel));
        } catch (CohortInputException e) {
            throw e;
        } catch (IOException e) {
            throw new CohortInputException(path + ": cannot read the download (" + reason(e) + ")");
        }
    }

    private List<Submission> resolveAll(Map<String, Student> students) throws IOException {
        List<Submission> submissions = new ArrayList<>();
        for (Student student : students.values()) {
            submissions.add(resolve(student));
        }
        Map<String, List<String>> shared = sharedIds(submissions);
        return submissions.stream().map(submission -> !shared.containsKey(submission.id()) ? submission
                : new Submission(submission.folder(), submission.id(), submission.fullName(), null, null,
                        "participant " + submission.id() + " has " + Listing.count(shared.get(submission.id()).size(),
                                "folder") + " in the download (" + Listing.some(shared.get(submission.id()))
                        + "): tick1 cannot tell which to grade, so it grades none of them"))
                .toList();
    }

    /**
     * The participant ids that more than one folder of the download carries, each with its folders
     * in order: Moodle gives a participant one folder, so two mean a download put together by hand,
     * and grading either would be a guess.
     */
    public static Map<String, List<String>> sharedIds(List<Submission> submissions) {
        Map<String, List<String>> folders = new TreeMap<>();
        submissions.forEach(submission -> folders.computeIfAbsent(submission.id(), id -> new ArrayList<>())
                .add(submission.folder()));
        folders.values().removeIf(list -> list.size() < 2);
        return folders;
    }

    /**
     * Whether the submission's folder (or, in a download without folders, its files) is named as Moodle names a
     * student's: only then is its id a participant's, whose row of the grading worksheet it may fill.
     */
    public static boolean namedByMoodle(Submission submission) {
        return StudentName.ofFolder(submission.folder()).moodles();
    }

    // ---------------------------------------------------------------------------------------------- the zip

    private Map<String, Student> readZip(Path path, FileChannel channel) throws IOException {
        ZipArchive zip;
        try {
            zip = ZipArchive.open(channel, limits.maxEntries());
        } catch (ZipArchive.Refused e) {
            throw new CohortInputException(path + ": " + e.getMessage());
        }
        Map<String, Student> students = new TreeMap<>();
        for (ZipArchive.Entry entry : zip.entries()) {
            int slash = entry.name().indexOf('/');
            String top = slash < 0 ? entry.name() : entry.name().substring(0, slash);
            if (passedOver(top)) {
                continue;
            }
            if (slash < 0 && !entry.directory()) {
                Student student = looseFile(students, top);
                if (student != null) {
                    student.add(looseName(top), outerReader(path, zip, entry));
                }
                continue;
            }
            Student student = students.computeIfAbsent(top, Student::new);
            if (slash >= 0 && !entry.directory()) {
                student.add(entry.name().substring(slash + 1), outerReader(path, zip, entry));
            }
        }
        return students;
    }

    /** An entry of the download: refusals inside it are the download's, a size over the cap the student's. */
    private Reader outerReader(Path path, ZipArchive zip, ZipArchive.Entry entry) {
        return cap -> {
            try {
                return zip.read(entry, cap);
            } catch (ZipArchive.Refused e) {
                throw new CohortInputException(path + ": " + e.getMessage());
            }
        };
    }

    // ------------------------------------------------------------------------------------------- the folder

    private Map<String, Student> readFolder(Path root) throws IOException {
        Map<String, Student> students = new TreeMap<>();
        List<Path> tops = new ArrayList<>();
        try (DirectoryStream<Path> listing = Files.newDirectoryStream(root)) {
            listing.forEach(tops::add);
        } catch (IOException e) {
            throw new CohortInputException(root + ": cannot read the folder (" + reason(e) + ")");
        }
        for (Path top : tops) {
            String name = top.getFileName().toString();
            if (passedOver(name)) {
                continue;
            }
            BasicFileAttributes attributes = Files.readAttributes(top, BasicFileAttributes.class,
                    LinkOption.NOFOLLOW_LINKS);
            if (attributes.isSymbolicLink()) {
                students.computeIfAbsent(name, Student::new)
                        .refuse(name + " is a symbolic link, which tick1 does not follow");
            } else if (attributes.isDirectory()) {
                walk(top, students.computeIfAbsent(name, Student::new));
            } else {
                Student student = looseFile(students, name);
                if (student != null) {
                    student.add(looseName(name), fileReader(top));
                }
            }
        }
        return students;
    }

    private void walk(Path folder, Student student) throws IOException {
        Files.walkFileTree(folder, Set.of(), Integer.MAX_VALUE, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attributes) throws IOException {
                if (++student.entries > limits.maxEntries()) {
                    student.refuse("the folder has more than " + limits.maxEntries() + " files");
                    return FileVisitResult.TERMINATE;
                }
                String relative = relative(folder, file);
                if (attributes.isSymbolicLink()) {
                    student.refuse(relative + " is a symbolic link, which tick1 does not follow");
                } else if (attributes.isRegularFile()) {
                    student.add(relative, fileReader(file));
                }
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFileFailed(Path file, IOException e) {
                student.refuse("cannot read " + relative(folder, file) + " (" + reason(e) + ")");
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult postVisitDirectory(Path directory, IOException e) {
                if (e != null) {
                    student.refuse("cannot read " + relative(folder, directory) + " (" + reason(e) + ")");
                }
                return FileVisitResult.CONTINUE;
            }
        });
    }

    /** A file on disk, opened without following a link, read no further than the cap. */
    private Reader fileReader(Path file) {
        return cap -> {
            try (SeekableByteChannel channel = Files.newByteChannel(file, StandardOpenOption.READ,
                    LinkOption.NOFOLLOW_LINKS)) {
                ByteBuffer buffer = ByteBuffer.allocate((int) Math.min(cap + 1, channel.size() + 1));
                while (buffer.hasRemaining() && channel.read(buffer) >= 0) {
                    continue;
                }
                if (buffer.position() > cap) {
                    throw new ZipArchive.TooLarge(file.getFileName() + " is larger than " + IntakeLimits.size(cap));
                }
                byte[] bytes = new byte[buffer.position()];
                buffer.flip().get(bytes);
                return bytes;
            } catch (ZipArchive.TooLarge e) {
                throw e;
            } catch (IOException e) {
                throw new ZipArchive.Refused("cannot read it (" + reason(e) + ")");
            }
        };
    }

    private static String relative(Path folder, Path file) {
        return folder.relativize(file).toString().replace('\\', '/');
    }

    // ------------------------------------------------------------------------------- what both forms share

    /** Hidden names and macOS's resource forks are nobody's submission. */
    private static boolean passedOver(String topName) {
        return topName.startsWith(".") || topName.equals(MAC_RESOURCES) || StudentName.isOtherSubmissionType(topName);
    }

    /**
     * A file at the top of the download: the student's when Moodle named it (a download without folders), else a
     * submission of its own that says it is outside any student's folder.
     */
    private Student looseFile(Map<String, Student> students, String fileName) {
        String[] moodle = StudentName.looseFileFolder(fileName);
        if (moodle != null) {
            return students.computeIfAbsent(moodle[0], Student::new);
        }
        students.computeIfAbsent(fileName, Student::new)
                .refuse(fileName + " is a file at the top of the download, not in a student's folder");
        return null;
    }

    private static String looseName(String fileName) {
        return StudentName.looseFileFolder(fileName)[1];
    }

    /** Reads a file's bytes, no more than {@code cap} of them. */
    @FunctionalInterface
    private interface Reader {
        byte[] read(long cap) throws IOException;
    }

    /** A file in a student's folder that may be one the tick asks for. */
    private record Candidate(String path, Reader reader) {
    }

    /** What was found in one student's folder so far. */
    private final class Student {
        final String folder;
        final List<Candidate> spheres = new ArrayList<>();
        final List<Candidate> renderers = new ArrayList<>();
        final List<String> refusals = new ArrayList<>();
        final List<String> unopened = new ArrayList<>();
        /** The .java files of other names, for a message when a file the tick asks for is missing. */
        final List<String> otherJava = new ArrayList<>();
        int entries;
        int files;
        long read;

        Student(String folder) {
            this.folder = folder;
        }

        void refuse(String why) {
            refusals.add(why);
        }

        /** Counts bytes read into memory against the student's budget, then the whole intake's. */
        byte[] charge(byte[] bytes) throws IOException {
            read += bytes.length;
            if (read > limits.maxStudentBytes()) {
                throw new OverBudget("the folder holds more than " + IntakeLimits.size(limits.maxStudentBytes())
                        + " of zips and source files to read");
            }
            return Submissions.this.charge(bytes);
        }

        /** A file of the student's, at {@code path} in their folder. */
        void add(String path, Reader reader) throws IOException {
            files++;
            String name = path.substring(path.lastIndexOf('/') + 1);
            if (candidate(name)) {
                (name.equals(SPHERE) ? spheres : renderers).add(new Candidate(path, reader));
            } else if (isZip(name)) {
                openNested(path, reader);
            } else if (isJava(name)) {
                otherJava.add(path);
            }
        }

        /** A zip in the student's folder: opened in memory, one level deep. */
        private void openNested(String path, Reader reader) throws IOException {
            ZipArchive zip;
            try {
                zip = ZipArchive.open(new SeekableInMemoryByteChannel(charge(reader.read(limits.maxNestedZipBytes()))),
                        limits.maxEntries());
            } catch (ZipArchive.TooLarge e) {
                refuse(path + " is larger than " + IntakeLimits.size(limits.maxNestedZipBytes())
                        + ", the largest zip tick1 opens");
                return;
            } catch (ZipArchive.Refused e) {
                refuse(path + ": " + e.getMessage());
                return;
            } catch (OverBudget e) {
                refuse(e.getMessage());
                return;
            }
            for (ZipArchive.Entry entry : zip.entries()) {
                if (entry.directory() || entry.name().startsWith(MAC_RESOURCES + "/")) {
                    continue;
                }
                String inner = path + "!/" + entry.name();
                String name = entry.name().substring(entry.name().lastIndexOf('/') + 1);
                if (candidate(name)) {
                    List<Candidate> same = name.equals(SPHERE) ? spheres : renderers;
                    same.add(new Candidate(inner, same.isEmpty() ? inflatedNow(zip, entry) : null));
                } else if (isZip(name)) {
                    unopened.add(inner);
                } else if (isJava(name)) {
                    otherJava.add(inner);
                }
            }
        }
    }

    /**
     * A file of a student's zip, inflated now, so that the zip need not stay in memory until the submission is
     * resolved; a failure is kept for then. Only a first candidate is inflated (a second one makes the submission
     * a problem, whatever it holds), so this holds at most two files' worth of memory per student.
     */
    private Reader inflatedNow(ZipArchive zip, ZipArchive.Entry entry) {
        try {
            byte[] bytes = zip.read(entry, limits.maxFileBytes());
            return cap -> bytes;
        } catch (IOException e) {
            return cap -> {
                throw e;
            };
        }
    }

    private static boolean candidate(String fileName) {
        return fileName.equals(SPHERE) || fileName.equals(RENDERER);
    }

    private static boolean isJava(String fileName) {
        return fileName.toLowerCase(Locale.ROOT).endsWith(".java");
    }

    private static boolean isZip(String fileName) {
        return fileName.toLowerCase(Locale.ROOT).endsWith(".zip");
    }

    /** A student's reads over their budget: their problem, not the download's. */
    private static final class OverBudget extends IOException {
        private static final long serialVersionUID = 1L;

        OverBudget(String message) {
            super(message);
        }
    }

    /** Counts bytes read into memory against the whole intake's budget. */
    private byte[] charge(byte[] bytes) throws CohortInputException {
        inflated += bytes.length;
        if (inflated > limits.maxTotalBytes()) {
            throw new CohortInputException(download + ": the download inflates to more than " + IntakeLimits.size(
                    limits.maxTotalBytes()) + " of files tick1 must read; refused as a zip bomb");
        }
        return bytes;
    }

    /** The student's submission, or the problem that stops it being graded. */
    private Submission resolve(Student student) throws IOException {
        StudentName name = StudentName.ofFolder(student.folder);
        List<String> problems = new ArrayList<>(student.refusals);
        if (problems.isEmpty() && student.files == 0) {
            problems.add("the folder is empty");
        }
        Submission.SourceFile sphere = null;
        Submission.SourceFile renderer = null;
        if (problems.isEmpty()) {
            String missing = missing(student);
            if (missing != null) {
                problems.add(missing);
            }
            for (List<Candidate> candidates : List.of(student.spheres, student.renderers)) {
                if (candidates.size() > 1) {
                    problems.add(Listing.count(candidates.size(), "file") + " could be " + fileName(candidates.get(0))
                            + ": " + Listing.some(candidates.stream().map(Candidate::path).toList()));
                }
            }
        }
        if (problems.isEmpty()) {
            try {
                sphere = read(student, student.spheres.get(0));
                renderer = read(student, student.renderers.get(0));
            } catch (ZipArchive.Refused | ZipArchive.TooLarge | OverBudget e) {
                problems.add(e.getMessage());
            }
        }
        if (!problems.isEmpty()) {
            return new Submission(student.folder, name.id(), name.fullName(), null, null, String.join("; ", problems));
        }
        return new Submission(student.folder, name.id(), name.fullName(), sphere, renderer, null);
    }

    private static String missing(Student student) {
        List<String> absent = new ArrayList<>();
        if (student.spheres.isEmpty()) {
            absent.add(SPHERE);
        }
        if (student.renderers.isEmpty()) {
            absent.add(RENDERER);
        }
        if (absent.isEmpty()) {
            return null;
        }
        String line = "no " + String.join(" or ", absent) + " in the submission";
        if (!student.otherJava.isEmpty()) {
            line += "; found " + Listing.some(student.otherJava) + ", but the tick's files must be named "
                    + SPHERE + " and " + RENDERER + " exactly (letter case too)";
        }
        if (!student.unopened.isEmpty()) {
            line += " (" + Listing.some(student.unopened) + (student.unopened.size() == 1 ? " is a zip" : " are zips")
                    + " inside a zip, which tick1 does not open)";
        }
        return line;
    }

    private Submission.SourceFile read(Student student, Candidate candidate) throws IOException {
        try {
            return new Submission.SourceFile(candidate.path(),
                    student.charge(candidate.reader().read(limits.maxFileBytes())));
        } catch (ZipArchive.TooLarge e) {
            throw new ZipArchive.TooLarge(candidate.path() + " is larger than "
                    + IntakeLimits.size(limits.maxFileBytes()) + ", far more than any " + fileName(candidate));
        } catch (ZipArchive.Refused e) {
            throw new ZipArchive.Refused(candidate.path() + ": " + e.getMessage());
        }
    }

    private static String fileName(Candidate candidate) {
        return candidate.path().substring(candidate.path().lastIndexOf('/') + 1);
    }

    private static String reason(IOException e) {
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }
}
