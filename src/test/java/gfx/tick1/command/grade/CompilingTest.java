package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * How {@code grade} compiles: in a JVM that runs none of the student's code, into classes that
 * every run of the code is given read-only; in a cohort, by each job's warm compiler, which
 * carries nothing from one submission to the next and is replaced when a compile breaks it.
 * Every grade here has grade's own time limit or a longer one: no behaviour here is about time, and
 * on a loaded machine a compile may take more than ten seconds by the clock.
 */
@ExtendWith(SandboxNeeded.class)
@Order(13)   // one of the longest classes: it starts early (junit-platform.properties)
class CompilingTest {

    private static final String[] SMALL = {"--width", "160", "--height", "120"};

    /**
     * A Renderer that leaves a mark beside its own classes, and renders black wherever it finds
     * one: where one run's writes reached a later run, its hidden scene would be black.
     */
    private static final String LEAVES_A_MARK = """
            try {
                java.nio.file.Path classes = java.nio.file.Path.of(
                        Renderer.class.getProtectionDomain().getCodeSource().getLocation().toURI());
                java.nio.file.Path mark = classes.resolve("mark");
                if (java.nio.file.Files.exists(mark)) {
                    return new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_RGB);
                }
                java.nio.file.Files.writeString(mark, "here before");
            } catch (Exception refused) {
                // A read-only folder: no mark.
            }
            return image;""";

    /** A Renderer that starts threads until it is refused one, and says how many it had. */
    private static final String COUNTS_ITS_THREADS = """
            int started = 0;
            try {
                for (; started < 4000; started++) {
                    Thread sleeper = new Thread(() -> {
                        try {
                            Thread.sleep(60_000);
                        } catch (InterruptedException e) {
                            return;
                        }
                    });
                    sleeper.setDaemon(true);
                    sleeper.start();
                }
            } catch (Throwable refused) {
                // The limit on processes and threads.
            }
            throw new IllegalStateException("started " + started + " threads");""";

    @TempDir
    Path dir;

    @Test
    void whatARunWritesBesideItsClassesNeverReachesTheHiddenScenesRun() throws IOException {
        CliRun grade = gradeAlone(StudentSolution.correct().editRenderer("return image;", LEAVES_A_MARK));

        assertThat(grade.out()).as(grade.transcript()).contains("hidden.xml: PASS")
                .contains("Congratulations! Your code passed the tester.");
    }

    @Test
    void theSubmissionAfterOneThatExhaustedTheCompilersMemoryCompilesAndPasses() throws IOException {
        Map<String, Map<String, String>> cohort = new LinkedHashMap<>();
        cohort.put("A Bomb_1001", Map.of("Sphere.java", StudentSolution.correct().sphere(),
                "Renderer.java", resource("/students/attacks/compiler-bomb/Renderer.java")));
        cohort.put("B Correct_1002", files(StudentSolution.correct()));

        // The time limit is long so that only memory can stop the compiler: on a loaded machine a
        // compiler collecting garbage near its heap limit may take more than ten seconds to give up.
        Map<String, String> rows = gradeOneAtATime(cohort, "--memory", "64", "--time-limit", "120");

        assertThat(rows.get("1001")).contains("the compiler ran out of memory");
        assertThat(rows.get("1002")).as("the submission after the one that broke the compiler")
                .contains("Congratulations!");
    }

    @Test
    void aWarmCompilerKnowsNothingOfTheSubmissionBefore() throws IOException {
        StudentSolution correct = StudentSolution.correct();
        // The first declares a class of its own beside Renderer; the second uses it without declaring it.
        StudentSolution declares = correct.editRenderer("return image;", "return image; } } class Helper { "
                + "static int one() { return 1; ");
        StudentSolution uses = correct.editRenderer("return image;", "Helper.one(); return image;");
        Map<String, Map<String, String>> cohort = new LinkedHashMap<>();
        cohort.put("A Declares_1001", files(declares));
        cohort.put("B Uses_1002", files(uses));

        Map<String, String> rows = gradeOneAtATime(cohort);

        assertThat(rows.get("1001")).contains("Congratulations!");
        assertThat(rows.get("1002")).contains("does not compile").contains("cannot find symbol");
    }

    @Test
    void aJobsWarmCompilerTakesNothingOfTheStudentsProcessLimit() throws IOException {
        StudentSolution counting = StudentSolution.correct().editRenderer("return image;", COUNTS_ITS_THREADS);
        CliRun alone = gradeAlone(counting);
        java.util.regex.Matcher count = java.util.regex.Pattern.compile("started (\\d+) threads")
                .matcher(alone.out());
        assertThat(count.find()).as(alone.transcript()).isTrue();

        int aloneCount = Integer.parseInt(count.group(1));

        String row = gradeOneAtATime(Map.of("Counts Threads_1001", files(counting))).get("1001");

        count = java.util.regex.Pattern.compile("started (\\d+) threads").matcher(row);
        assertThat(count.find()).as(row).isTrue();
        // A compiler under the student's user would take its 14 threads (66 against 80). The count
        // varies by a few from run to run (the JVM starts some threads lazily, and processes of
        // earlier runs under the same user may still be exiting), so half of that is allowed.
        assertThat(Integer.parseInt(count.group(1))).as("threads with the job's compiler alive beside it: " + row)
                .isGreaterThanOrEqualTo(aloneCount - 7);
    }

    /** Grades one student's files with {@code tick1 grade --sphere --renderer}. */
    private CliRun gradeAlone(StudentSolution solution) throws IOException {
        Path sphere = Files.writeString(dir.resolve("Sphere.java"), solution.sphere());
        Path renderer = Files.writeString(dir.resolve("Renderer.java"), solution.renderer());
        return CliRun.of(withSmall("grade", "--sphere", sphere.toString(), "--renderer", renderer.toString(),
                "--report", dir.resolve("alone").toString()));
    }

    /** Grades the cohort with one job, so that one warm compiler compiles every submission in order. */
    private Map<String, String> gradeOneAtATime(Map<String, Map<String, String>> cohort, String... options)
            throws IOException {
        Path zip = dir.resolve("download.zip");
        try (ZipOutputStream out = new ZipOutputStream(Files.newOutputStream(zip))) {
            for (var student : cohort.entrySet()) {
                for (var file : student.getValue().entrySet()) {
                    out.putNextEntry(new ZipEntry(student.getKey() + "_assignsubmission_file_/" + file.getKey()));
                    out.write(file.getValue().getBytes(StandardCharsets.UTF_8));
                    out.closeEntry();
                }
            }
        }
        Path report = dir.resolve("report");
        String[] args = withSmall("grade", "--submissions", zip.toString(), "--report", report.toString(),
                "--jobs", "1");
        List<String> all = new java.util.ArrayList<>(List.of(args));
        all.addAll(List.of(options));
        CliRun grade = CliRun.of(all.toArray(String[]::new));
        assertThat(report.resolve("grades.csv")).as(grade.transcript()).isRegularFile();
        Map<String, String> rows = new LinkedHashMap<>();
        for (String line : Files.readAllLines(report.resolve("grades.csv"))) {
            rows.put(line.split(",", 2)[0].replace("\"", "").replace("Participant ", ""), line);
        }
        return rows;
    }

    private static String[] withSmall(String... args) {
        List<String> all = new java.util.ArrayList<>(List.of(args));
        all.addAll(List.of(SMALL));
        return all.toArray(String[]::new);
    }

    private static Map<String, String> files(StudentSolution solution) {
        return Map.of("Sphere.java", solution.sphere(), "Renderer.java", solution.renderer());
    }

    private static String resource(String name) throws IOException {
        try (InputStream in = CompilingTest.class.getResourceAsStream(name)) {
            assertThat(in).as(name).isNotNull();
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            in.transferTo(bytes);
            return bytes.toString(StandardCharsets.UTF_8);
        }
    }
}
