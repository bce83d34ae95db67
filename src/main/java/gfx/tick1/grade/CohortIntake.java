package gfx.tick1.grade;

import gfx.tick1.grade.cohort.Submission;
import gfx.tick1.grade.cohort.Submission.SourceFile;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;

/**
 * Reads a cohort's download into submissions: a folder, or a zip of one, whose top-level folders
 * are the students ({@code Full Name_<participant id>_assignsubmission_file_} as Moodle names them,
 * any other name being the student's id), with {@code Sphere.java} and {@code Renderer.java}
 * anywhere inside, a nested zip included. This is the plain reading the grader needs; the hostile
 * archive checks belong to the cohort intake, which takes its place.
 */
final class CohortIntake {

    private static final Pattern MOODLE_FOLDER = Pattern.compile("(.+)_(\\d+)_assignsubmission_file_?");
    /** The most bytes read from an archive in all: a budget against zip bombs. */
    private static final long BUDGET = 256L << 20;

    private CohortIntake() {
    }

    /** The submissions in {@code download}, sorted by folder name. */
    static List<Submission> read(Path download) throws IOException {
        Map<String, Map<String, byte[]>> students = new TreeMap<>();
        if (Files.isDirectory(download)) {
            try (Stream<Path> tops = Files.list(download)) {
                for (Path top : tops.sorted(Comparator.comparing(Path::toString)).toList()) {
                    if (Files.isDirectory(top, LinkOption.NOFOLLOW_LINKS)) {
                        Map<String, byte[]> files = new LinkedHashMap<>();
                        try (Stream<Path> all = Files.walk(top)) {
                            for (Path file : all.filter(f -> Files.isRegularFile(f, LinkOption.NOFOLLOW_LINKS))
                                    .sorted().toList()) {
                                files.put(top.relativize(file).toString(), Files.readAllBytes(file));
                            }
                        }
                        students.put(top.getFileName().toString(), files);
                    }
                }
            }
        } else {
            long[] budget = {BUDGET};
            try (InputStream in = Files.newInputStream(download)) {
                unzip(in, "", budget).forEach((name, bytes) -> {
                    int slash = name.indexOf('/');
                    if (slash > 0) {
                        students.computeIfAbsent(name.substring(0, slash), k -> new LinkedHashMap<>())
                                .put(name.substring(slash + 1), bytes);
                    }
                });
            }
        }
        List<Submission> submissions = new ArrayList<>();
        students.forEach((folder, files) -> submissions.add(submission(folder, files)));
        return submissions;
    }

    private static Map<String, byte[]> unzip(InputStream in, String prefix, long[] budget) throws IOException {
        Map<String, byte[]> files = new LinkedHashMap<>();
        ZipInputStream zip = new ZipInputStream(in);
        for (ZipEntry entry; (entry = zip.getNextEntry()) != null; ) {
            if (entry.isDirectory()) {
                continue;
            }
            byte[] bytes = zip.readNBytes((int) Math.min(Integer.MAX_VALUE - 16, budget[0] + 1));
            budget[0] -= bytes.length;
            if (budget[0] < 0) {
                throw new IOException("the archive holds more than " + (BUDGET >> 20) + " MiB");
            }
            files.put(prefix + entry.getName(), bytes);
        }
        return files;
    }

    private static Submission submission(String folder, Map<String, byte[]> files) {
        Matcher moodle = MOODLE_FOLDER.matcher(folder);
        String id = moodle.matches() ? moodle.group(2) : folder;
        String name = moodle.matches() ? moodle.group(1) : folder;
        Map<String, byte[]> all = new LinkedHashMap<>();
        files.forEach((path, bytes) -> {
            if (path.endsWith(".zip")) {
                try {
                    unzip(new ByteArrayInputStream(bytes), path + "!/", new long[] {BUDGET})
                            .forEach(all::put);
                } catch (IOException e) {
                    all.put(path, bytes);
                }
            } else {
                all.put(path, bytes);
            }
        });
        if (all.isEmpty()) {
            return new Submission(folder, id, name, null, null, "the submission is empty");
        }
        SourceFile sphere = null, renderer = null;
        List<String> problems = new ArrayList<>();
        for (String wanted : List.of("Sphere.java", "Renderer.java")) {
            List<String> found = all.keySet().stream()
                    .filter(path -> path.equals(wanted) || path.endsWith("/" + wanted)).toList();
            if (found.isEmpty()) {
                problems.add("no " + wanted + " in the submission");
            } else if (found.size() > 1) {
                problems.add("two or more files called " + wanted + " in the submission (" + String.join(", ", found)
                        + ")");
            } else {
                SourceFile file = new SourceFile(found.get(0), all.get(found.get(0)));
                if (wanted.startsWith("Sphere")) {
                    sphere = file;
                } else {
                    renderer = file;
                }
            }
        }
        return problems.isEmpty() ? new Submission(folder, id, name, sphere, renderer, null)
                : new Submission(folder, id, name, null, null, String.join("; ", problems));
    }
}
