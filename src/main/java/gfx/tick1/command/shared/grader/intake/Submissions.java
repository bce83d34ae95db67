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

    /** Where macOS's archiver keeps resource forks: never a student. */
    static final String MAC_RESOURCES = "__MACOSX";

    private final Path download;
    private final IntakeLimits limits;
    private long inflated;
    /** The files at the top of the download that Moodle did not name: no student's, each a problem of its own. */
    private final List<String> loose = new ArrayList<>();

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
        boolean folder = Files.isDirectory(path);
        if (!folder && !Files.isRegularFile(path)) {
            throw new CohortInputException(path + ": " + FileKind.notAFileOrFolder(path));
        }
        Optional<String> notZip = folder ? Optional.empty() : FileKind.unlessZip(path);
        if (notZip.isPresent()) {
            throw new CohortInputException(path + ": " + notZip.get() + ", not a zip: --submissions wants Moodle's "
                    + "\"Download all submissions\" zip, or the folder it unpacks to (a grading worksheet goes to "
                    + "--worksheet)");
        }
        // The zip's entries are read while its channel is open: the submissions are resolved inside.
        try (FileChannel channel = folder ? null : FileChannel.open(path, StandardOpenOption.READ)) {
            return intake.resolveAll(folder ? intake.readFolder(path) : intake.readZip(path, channel));
        } catch (CohortInputException e) {
            throw e;
        } catch (IOException e) {
            throw new CohortInputException(path + ": cannot read the " + (folder ? "folder" : "download") + " ("
                    + reason(e) + ")");
        }
    }

    private List<Submission> resolveAll(Map<String, StudentFolder> students) throws IOException {
        if (loose.size() == students.size()) {
            throw new CohortInputException(download + ": no submissions: " + (loose.isEmpty()
                    ? "the download holds no student's folder of files"
                    : "it holds no student's folder, only files (" + oneLine(Listing.some(loose.stream()
                            .sorted().toList())) + ")"
                    + loose.stream().sorted().filter(name -> Files.isDirectory(download)
                            && name.toLowerCase(Locale.ROOT).endsWith(".zip")).findFirst()
                            .map(zip -> "; --submissions wants the download itself: " + oneLine(download
                                    .resolve(zip).toString()))
                            .orElse("")));
        }
        List<Submission> submissions = new ArrayList<>();
        for (StudentFolder student : students.values()) {
            submissions.add(student.resolve());
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

    private Map<String, StudentFolder> readZip(Path path, FileChannel channel) throws IOException {
        ZipArchive zip;
        try {
            zip = ZipArchive.open(channel, limits.maxEntries());
        } catch (ZipArchive.Refused e) {
            throw new CohortInputException(path + ": " + e.getMessage());
        }
        Map<String, StudentFolder> students = new TreeMap<>();
        Map<String, List<String>> inside = new TreeMap<>();
        for (ZipArchive.Entry entry : zip.entries()) {
            int slash = entry.name().indexOf('/');
            String top = slash < 0 ? entry.name() : entry.name().substring(0, slash);
            if (passedOver(top)) {
                continue;
            }
            inside.computeIfAbsent(top, name -> new ArrayList<>()).add(entry.name().substring(slash + 1)
                    .replaceFirst("/.*", ""));
            if (slash < 0 && !entry.directory()) {
                StudentFolder student = looseFile(students, top);
                if (student != null) {
                    student.add(looseName(top), outerReader(path, zip, entry));
                }
                continue;
            }
            StudentFolder student = students.computeIfAbsent(top, this::studentFolder);
            if (slash >= 0 && !entry.directory()) {
                student.add(entry.name().substring(slash + 1), outerReader(path, zip, entry));
            }
        }
        String holding = StudentName.holdingTheDownload(inside);
        if (holding != null) {
            throw new CohortInputException(path + ": the zip holds the download in its folder " + oneLine(holding)
                    + ", not the students' folders; --submissions wants Moodle's zip itself, or that folder unpacked");
        }
        return students;
    }

    /** An entry of the download: refusals inside it are the download's, a size over the cap the student's. */
    private StudentFolder.Reader outerReader(Path path, ZipArchive zip, ZipArchive.Entry entry) {
        return cap -> {
            try {
                return zip.read(entry, cap);
            } catch (ZipArchive.Refused e) {
                throw new CohortInputException(path + ": " + e.getMessage());
            }
        };
    }

    // ------------------------------------------------------------------------------------------- the folder

    private Map<String, StudentFolder> readFolder(Path root) throws IOException {
        Map<String, StudentFolder> students = new TreeMap<>();
        List<Path> tops = new ArrayList<>();
        try (DirectoryStream<Path> listing = Files.newDirectoryStream(root)) {
            listing.forEach(tops::add);
        } catch (IOException e) {
            throw new CohortInputException(root + ": cannot read the folder (" + reason(e) + ")");
        }
        String holding = StudentName.holdingTheDownload(inside(tops));
        if (holding != null) {
            throw new CohortInputException(root + ": the folder holds the download, not the students' folders; "
                    + "--submissions wants the download itself: " + oneLine(root.resolve(holding).toString()));
        }
        for (Path top : tops) {
            String name = top.getFileName().toString();
            if (passedOver(name)) {
                continue;
            }
            BasicFileAttributes attributes = Files.readAttributes(top, BasicFileAttributes.class,
                    LinkOption.NOFOLLOW_LINKS);
            if (attributes.isSymbolicLink()) {
                students.computeIfAbsent(name, this::studentFolder)
                        .refuse(name + " is a symbolic link, which tick1 does not follow");
            } else if (attributes.isDirectory()) {
                walk(top, students.computeIfAbsent(name, this::studentFolder));
            } else {
                StudentFolder student = looseFile(students, name);
                if (student != null) {
                    student.add(looseName(name), fileReader(top));
                }
            }
        }
        return students;
    }

    /** The names in each of the folders among {@code tops}, by the folder's name (a link is no folder). */
    private static Map<String, List<String>> inside(List<Path> tops) throws IOException {
        Map<String, List<String>> inside = new TreeMap<>();
        for (Path top : tops) {
            List<String> names = inside.computeIfAbsent(top.getFileName().toString(), name -> new ArrayList<>());
            if (Files.isDirectory(top, LinkOption.NOFOLLOW_LINKS)) {
                try (DirectoryStream<Path> entries = Files.newDirectoryStream(top)) {
                    entries.forEach(entry -> names.add(entry.getFileName().toString()));
                }
            }
        }
        return inside;
    }

    private void walk(Path folder, StudentFolder student) throws IOException {
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
    private StudentFolder.Reader fileReader(Path file) {
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
    private StudentFolder looseFile(Map<String, StudentFolder> students, String fileName) {
        String[] moodle = StudentName.looseFileFolder(fileName);
        if (moodle != null) {
            return students.computeIfAbsent(moodle[0], this::studentFolder);
        }
        students.computeIfAbsent(fileName, this::studentFolder)
                .refuse(fileName + " is a file at the top of the download, not in a student's folder");
        loose.add(fileName);
        return null;
    }

    private static String looseName(String fileName) {
        return StudentName.looseFileFolder(fileName)[1];
    }

    /** Counts bytes read into memory against the whole intake's budget. */
    byte[] charge(byte[] bytes) throws CohortInputException {
        inflated += bytes.length;
        if (inflated > limits.maxTotalBytes()) {
            throw new CohortInputException(download + ": the download inflates to more than " + IntakeLimits.size(
                    limits.maxTotalBytes()) + " of files tick1 must read; refused as a zip bomb");
        }
        return bytes;
    }

    private StudentFolder studentFolder(String folder) {
        return new StudentFolder(folder, limits, this);
    }

    /** Names from the download as one line: a control character (a newline in a file name) is a {@code ?}. */
    private static String oneLine(String names) {
        return names.replaceAll("\\p{Cntrl}", "?");
    }

    private static String reason(IOException e) {
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }
}
