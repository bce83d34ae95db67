package gfx.tick1.command.shared.grader.intake;

import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.apache.commons.compress.utils.SeekableInMemoryByteChannel;

/**
 * What was found in one student's folder of a cohort's download so far, read within {@link IntakeLimits}, and the
 * submission it makes, or the problem that stops it being graded.
 */
final class StudentFolder {

    static final String SPHERE = "Sphere.java";
    static final String RENDERER = "Renderer.java";

    /** Reads a file's bytes, no more than {@code cap} of them. */
    @FunctionalInterface
    interface Reader {
        byte[] read(long cap) throws IOException;
    }

    /** A file in a student's folder that may be one the tick asks for. */
    record Candidate(String path, Reader reader) {
    }

    private final String folder;
    private final IntakeLimits limits;
    /** The whole intake, whose budget every read counts against too. */
    private final Submissions intake;
    private final List<Candidate> spheres = new ArrayList<>();
    private final List<Candidate> renderers = new ArrayList<>();
    private final List<String> refusals = new ArrayList<>();
    private final List<String> unopened = new ArrayList<>();
    /** The .java files of other names, for a message when a file the tick asks for is missing. */
    private final List<String> otherJava = new ArrayList<>();
    int entries;
    private int files;
    private long read;

    StudentFolder(String folder, IntakeLimits limits, Submissions intake) {
        this.folder = folder;
        this.limits = limits;
        this.intake = intake;
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
        return intake.charge(bytes);
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
            if (entry.directory() || entry.name().startsWith(Submissions.MAC_RESOURCES + "/")) {
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

    /** The student's submission, or the problem that stops it being graded. */
    Submission resolve() throws IOException {
        StudentName name = StudentName.ofFolder(folder);
        List<String> problems = new ArrayList<>(refusals);
        if (problems.isEmpty() && files == 0) {
            problems.add("the folder is empty");
        }
        Submission.SourceFile sphere = null;
        Submission.SourceFile renderer = null;
        if (problems.isEmpty()) {
            String missing = missing();
            if (missing != null) {
                problems.add(missing);
            }
            for (List<Candidate> candidates : List.of(spheres, renderers)) {
                if (candidates.size() > 1) {
                    problems.add(Listing.count(candidates.size(), "file") + " could be " + fileName(candidates.get(0))
                            + ": " + Listing.some(candidates.stream().map(Candidate::path).toList()));
                }
            }
        }
        if (problems.isEmpty()) {
            try {
                sphere = read(spheres.get(0));
                renderer = read(renderers.get(0));
            } catch (ZipArchive.Refused | ZipArchive.TooLarge | OverBudget e) {
                problems.add(e.getMessage());
            }
        }
        if (!problems.isEmpty()) {
            return new Submission(folder, name.id(), name.fullName(), null, null, String.join("; ", problems));
        }
        return new Submission(folder, name.id(), name.fullName(), sphere, renderer, null);
    }

    private String missing() {
        List<String> absent = new ArrayList<>();
        if (spheres.isEmpty()) {
            absent.add(SPHERE);
        }
        if (renderers.isEmpty()) {
            absent.add(RENDERER);
        }
        if (absent.isEmpty()) {
            return null;
        }
        String line = "no " + String.join(" or ", absent) + " in the submission";
        if (!otherJava.isEmpty()) {
            line += "; found " + Listing.some(otherJava) + ", but the tick's files must be named "
                    + SPHERE + " and " + RENDERER + " exactly (letter case too)";
        }
        if (!unopened.isEmpty()) {
            line += " (" + Listing.some(unopened) + (unopened.size() == 1 ? " is a zip" : " are zips")
                    + " inside a zip, which tick1 does not open)";
        }
        return line;
    }

    private Submission.SourceFile read(Candidate candidate) throws IOException {
        try {
            return new Submission.SourceFile(candidate.path(),
                    charge(candidate.reader().read(limits.maxFileBytes())));
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
}
