package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.Tick1;
import gfx.tick1.command.preview.HeadlessChromium;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.grader.cohort.StoredCode;
import gfx.tick1.command.shared.grader.grading.HiddenVerdict;
import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.report.Worksheet;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.openqa.selenium.By;
import org.openqa.selenium.support.ui.ExpectedConditions;

/**
 * {@code tick1 grade --submissions} on a generated cohort in Moodle's download form: correct
 * solutions laid out as students lay them out, one submission for each mistake of the diagnose
 * catalogue, and the submissions a cohort always has (a missing file, code that does not compile,
 * an infinite loop, a cheat, a nested zip). Every row of grades.csv is checked against the grade
 * each submission must get, and the feedback of each mistake and each kind of failure against what
 * it must say. One cohort is graded once for the whole class; the tests of resuming, stopping and
 * the cohort's options grade small cohorts of their own.
 */
@ExtendWith(SandboxNeeded.class)
@Order(4)   // one of the longest classes: it starts early (junit-platform.properties)
class GradeCohortTest {

    private static final String[] SMALL = {"--width", "160", "--height", "120"};
    private static final String NEAR_ROOT = "double s = s1 > 0 ? s1 : s2;";

    @TempDir
    static Path shared;

    /** One student of the generated cohort: the folder Moodle gives them, their files, and the grade they must get. */
    record Student(String name, int id, Map<String, byte[]> files, boolean passes) {
        String folder() {
            return name + "_" + id + "_assignsubmission_file_";
        }
    }

    private static List<Student> cohort;
    private static CliRun firstRun;

    @BeforeAll
    static void gradeTheGeneratedCohort() throws IOException {
        cohort = generatedCohort();
        firstRun = CliRun.of(gradeArguments(moodleZip(shared.resolve("download.zip"), cohort),
                shared.resolve("report")));
    }

    /**
     * grade's arguments for a cohort: small images, and a time limit of 20 s unless {@code more} gives one: short, as
     * a student loops until it, but one that a job's first compile, which starts its compiler, keeps within on a
     * loaded machine.
     */
    static String[] gradeArguments(Path submissions, Path report, String... more) {
        List<String> args = new ArrayList<>(List.of("grade", "--submissions", submissions.toString(),
                "--report", report.toString()));
        args.addAll(List.of(SMALL));
        if (!List.of(more).contains("--time-limit")) {
            args.addAll(List.of("--time-limit", "20"));
        }
        args.addAll(List.of(more));
        return args.toArray(String[]::new);
    }

    /**
     * About forty students: one of each kind a year of Tick 1 submissions holds (each correct layout, each catalogued
     * mistake, each way to fail), so that each is graded once.
     */
    static List<Student> generatedCohort() throws IOException {
        List<Student> students = new ArrayList<>();
        StudentSolution correct = StudentSolution.correct();
        int id = 1000;
        // Correct solutions, each a little different (as no two students' files are the same), in the layouts
        // students use: the files alone, the kit's src/gfx/tick1 folders, and a zip inside the submission.
        for (int i = 0; i < 2; i++) {
            StudentSolution own = correct.editRenderer("return image;", "return image; // student " + i);
            students.add(new Student("Correct Student " + i, id++, i % 2 == 0 ? files(own)
                    : files("src/gfx/tick1/", own), true));
        }
        students.add(new Student("Zipped Twice", id++, Map.of("tick1.zip", zip(files(correct))), true));
        students.add(new Student("Zoë Ünïcode-Ñame", id++, files(correct), true));
        students.add(new Student("Byte Order", id++, files(new StudentSolution("\uFEFF" + correct.sphere(),
                "\uFEFF" + correct.renderer())), true));
        // A mistake that shows only with the camera inside a sphere: the default scenes cannot see it.
        students.add(new Student("Inside Sphere", id++, files(Mistakes.HIT_REJECTED_ON_A_NEGATIVE_ROOT), true));
        for (var mistake : Mistakes.onTheCoursesScenes().toList()) {
            Variant variant = (Variant) mistake.get()[0];
            students.add(new Student(mistakesName(variant), id++, files((StudentSolution) mistake.get()[1]), false));
        }
        Map<String, byte[]> missing = new LinkedHashMap<>(files(correct));
        missing.remove("Renderer.java");
        students.add(new Student("Missing Renderer", id++, missing, false));
        students.add(new Student("Does Not Compile", id++, files(correct.editSphere(NEAR_ROOT,
                "double s = s1 > 0 ? s1 : s2")), false));
        students.add(new Student("Missing Method", id++, files(correct.editRenderer("k_d * Math.max(0, NdotL)",
                "k_d * N.dotProduct(L)")), false));
        // It loops without using the processor: the time limit is a wall clock's, which stops a busy loop alike.
        students.add(new Student("Loops Forever", id++, files(correct.editSphere(NEAR_ROOT,
                NEAR_ROOT + " while (s > 0) { java.util.concurrent.locks.LockSupport.parkNanos(1_000_000_000L); }")),
                false));
        students.add(new Student("Copies The Reference", id++, files(new StudentSolution(correct.sphere(),
                resource("/students/attacks/copy-the-reference/Renderer.java"))), false));
        students.add(new Student("Throws", id++, files(correct.editRenderer("L.reflectIn(N)", "L.reflectIn(null)")),
                false));
        students.add(new Student("Exits", id++, files(correct.editRenderer("return image;",
                "System.exit(0); return image;")), false));
        students.add(new Student("Other Package", id++, files(correct.editSphere("package gfx.tick1;",
                "package tick1;")), false));
        // Comments and blank lines that overflowed the stack of a grader parsing the package by a regex, and a
        // package line that never ends, which it parsed in quadratic time: each is one student's grade alone.
        students.add(new Student("Comment Flood", id++, files(new StudentSolution("//\n".repeat(1_600)
                + correct.sphere(), "/* x */\n".repeat(800) + "\n".repeat(1_700) + correct.renderer())), true));
        students.add(new Student("Endless Package", id++, files(new StudentSolution("package gfx"
                + " ".repeat(320 * 1024), correct.renderer())), false));
        Map<String, byte[]> twice = new LinkedHashMap<>(files(correct));
        twice.put("old/Sphere.java", correct.sphere().getBytes(StandardCharsets.UTF_8));
        students.add(new Student("Two Spheres", id++, twice, false));
        students.add(new Student("Latin One", id++, Map.of("Sphere.java", correct.sphere().getBytes(
                StandardCharsets.UTF_8), "Renderer.java",
                correct.renderer().replace("// The colour", "// Th\u00e9 colour")
                .getBytes(StandardCharsets.ISO_8859_1)), false));
        return students;
    }

    /** The name of the student who makes {@code mistake}. */
    private static String mistakesName(Variant mistake) {
        return "Mistake " + mistake.name().replace('_', ' ');
    }

    private static Student student(String name) {
        return cohort.stream().filter(s -> s.name().equals(name)).findFirst().orElseThrow(
                () -> new AssertionError("no student " + name + " in the cohort"));
    }

    /** grades.csv's row of the student named {@code name} in the cohort's report. */
    private static List<String> row(String name) throws IOException {
        return rows(shared.resolve("report")).get("Participant " + student(name).id());
    }

    /** The lines of the plain-text feedback (feedback.txt) that the cohort's report gives the student named. */
    private static List<String> feedback(String name) throws IOException {
        return Files.readAllLines(shared.resolve("report").resolve("feedback").resolve(student(name).folder())
                .resolve("feedback.txt"));
    }

    static Map<String, byte[]> files(StudentSolution solution) {
        return files("", solution);
    }

    private static Map<String, byte[]> files(String folder, StudentSolution solution) {
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put(folder + "Sphere.java", solution.sphere().getBytes(StandardCharsets.UTF_8));
        files.put(folder + "Renderer.java", solution.renderer().getBytes(StandardCharsets.UTF_8));
        return files;
    }

    static String resource(String name) throws IOException {
        try (var in = GradeCohortTest.class.getResourceAsStream(name)) {
            assertThat(in).as(name).isNotNull();
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    static byte[] zip(Map<String, byte[]> files) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ZipOutputStream zip = new ZipOutputStream(bytes)) {
            for (Map.Entry<String, byte[]> file : files.entrySet()) {
                zip.putNextEntry(new ZipEntry(file.getKey()));
                zip.write(file.getValue());
                zip.closeEntry();
            }
        }
        return bytes.toByteArray();
    }

    /** The cohort as Moodle's "Download all submissions" zip: one folder per student. */
    static Path moodleZip(Path zip, List<Student> students) throws IOException {
        Map<String, byte[]> all = new LinkedHashMap<>();
        for (Student student : students) {
            student.files().forEach((name, bytes) -> all.put(student.folder() + "/" + name, bytes));
        }
        Files.write(zip, zip(all));
        return zip;
    }

    /** grades.csv's rows after the header, by identifier. */
    static Map<String, List<String>> rows(Path report) throws IOException {
        List<String> lines = Files.readString(report.resolve("grades.csv")).lines().toList();
        assertThat(lines.get(0)).isEqualTo(String.join(",", Worksheet.HEADER));
        Map<String, List<String>> rows = new LinkedHashMap<>();
        for (String line : lines.subList(1, lines.size())) {
            List<String> cells = csvCells(line);
            rows.put(cells.get(0), cells);
        }
        return rows;
    }

    private static List<String> csvCells(String line) {
        List<String> cells = new ArrayList<>();
        StringBuilder cell = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quoted && c == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                cell.append('"');
                i++;
            } else if (c == '"') {
                quoted = !quoted;
            } else if (c == ',' && !quoted) {
                cells.add(cell.toString());
                cell.setLength(0);
            } else {
                cell.append(c);
            }
        }
        cells.add(cell.toString());
        return cells;
    }

    @Test
    void everyStudentGetsTheGradeTheirSubmissionDeserves() throws IOException {
        assertThat(firstRun.status()).as(firstRun.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        Map<String, List<String>> rows = rows(shared.resolve("report"));
        assertThat(rows).as(firstRun.transcript()).hasSize(cohort.size());
        for (Student student : cohort) {
            List<String> row = rows.get("Participant " + student.id());
            assertThat(row).as(student.name()).isNotNull();
            assertThat(row.get(1)).isEqualTo(student.name());
            // A submission whose files could not be used is never run: its grade is left blank for staff.
            boolean unusable = student.name().equals("Missing Renderer") || student.name().equals("Two Spheres");
            assertThat(row.get(4)).as(student.name() + ": " + row.get(9))
                    .isEqualTo(student.passes() ? "1.00" : unusable ? "" : "0.00");
            assertThat(row.get(5)).isEqualTo("1.00");
        }
    }

    @Test
    void theClosingSummaryNamesTheGradesTheFeedbackZipAndThePage() {
        Path report = shared.resolve("report");
        assertThat(firstRun.out()).as(firstRun.transcript()).contains("Grades: " + report.resolve("grades.csv")
                + "; feedback: " + report.resolve("feedback.zip") + "; report: " + report.resolve("index.html"));
        assertThat(report.resolve("feedback.zip")).as("the zip the summary names").isRegularFile();
    }

    /**
     * The compiler's words as javac prints them: the error, the source line, and a caret under the place,
     * in the student's feedback.txt and feedback.html and on the cohort's page.
     */
    @Test
    void aCompileErrorsFeedbackKeepsTheSourceLineAndTheCaretUnderIt() throws IOException {
        Path report = shared.resolve("report");
        Path folder = report.resolve("feedback").resolve(student("Does Not Compile").folder());
        assertCaretAfterTheSourceLine("feedback.txt", Files.readString(folder.resolve("feedback.txt")));
        assertCaretAfterTheSourceLine("feedback.html", Files.readString(folder.resolve("feedback.html")));
        assertCaretAfterTheSourceLine("the cohort's page", Files.readString(report.resolve("index.html")));
    }

    /** {@code page} shows the line that does not compile, with a caret on the next line just after its s2. */
    private static void assertCaretAfterTheSourceLine(String what, String page) {
        String source = "double s = s1 > 0 ? s1 : s2";
        List<String> lines = page.replace("&gt;", ">").replace("&lt;", "<").replace("&amp;", "&").lines().toList();
        int at = 0;
        while (at < lines.size() - 1 && !lines.get(at).contains(source)) {
            at++;
        }
        assertThat(lines.get(at)).as("%s:%n%s", what, page).contains(source);
        String caret = lines.get(at + 1);
        assertThat(caret.strip()).as("%s: the line under the source line", what).isEqualTo("^");
        assertThat(caret.indexOf('^')).as("%s: the caret's column, just after s2, where the ';' is missing", what)
                .isEqualTo(lines.get(at).indexOf(source) + source.length());
    }

    @Test
    void eachFailureSaysWhyInTheFeedbackCell() throws IOException {
        Map<String, List<String>> rows = rows(shared.resolve("report"));
        Map<String, String> reasons = new LinkedHashMap<>();
        cohort.forEach(student -> reasons.put(student.name(), rows.get("Participant " + student.id()).get(9)));
        assertThat(reasons.get("Correct Student 0")).isEqualTo(SubmissionGrader.CONGRATULATIONS);
        // No hit from inside a sphere is what the handout's six steps give: a correct answer, with nothing to note.
        assertThat(reasons.get("Inside Sphere")).as("a pass").isEqualTo(SubmissionGrader.CONGRATULATIONS);
        assertThat(reasons.get("Missing Renderer")).contains("Renderer.java");
        assertThat(reasons.get("Does Not Compile")).contains("does not compile", "Sphere.java:");
        assertThat(reasons.get("Loops Forever")).contains("time limit");
        assertThat(reasons.get("Copies The Reference")).contains("ClassNotFoundException");
        assertThat(reasons.get("Other Package")).contains("package gfx.tick1");
        assertThat(reasons.get("Latin One")).contains("not UTF-8");
        // The reason gives the catalogue's exact image match first, then what the methods' answers show.
        assertThat(reasons.get("Mistake UNCLAMPED N DOT L"))
                .contains("is exactly the image of \"" + Variant.UNCLAMPED_N_DOT_L.title() + "\".")
                .contains("Your illuminate gives the answers of \"" + Variant.UNCLAMPED_N_DOT_L.title() + "\" on all ");
        assertThat(reasons.values()).allMatch(reason -> !reason.contains("\n"));
    }

    /**
     * The year at a glance counts, under each catalogued mistake, the students whose wrong image that entry
     * reproduces exactly: a mistake of render's, which no probe of intersectionWith and illuminate names, is
     * found by its image alone.
     */
    @Test
    void theYearAtAGlanceCountsEachCataloguedMistakeAStudentsImageIsExactly() throws IOException {
        String page = Files.readString(shared.resolve("report").resolve("index.html"));
        int start = page.indexOf("<h3>Catalogued mistakes");
        String catalogued = page.substring(start, page.indexOf("<h3>", start + 1));
        for (Variant mistake : Mistakes.RENDER_ONLY) {
            assertThat(catalogued).as("the year at a glance's catalogued mistakes").contains("<tr><td>"
                    + mistake.title() + "</td><td>1</td><td>0</td></tr>");
        }
    }

    /** A mistake of render's sends its student, at the top of the feedback, to its catalogue entry's section. */
    @Test
    void theFeedbackSaysToRereadTheSectionOfTheCataloguedMistake() throws IOException {
        for (Variant mistake : Mistakes.RENDER_ONLY) {
            List<String> feedback = feedback(mistakesName(mistake));
            assertThat(feedback).as(String.join("\n", feedback))
                    .containsSubsequence("What to reread", "  - " + capitalised(Variant.where(mistake.reread())) + ".",
                            "tick1.xml: failed");
        }
    }

    @Test
    void aFailingStudentsFeedbackFolderHoldsThePageAndTheHeatMap() {
        Student student = student(mistakesName(Variant.UNCLAMPED_N_DOT_L));
        Path feedback = shared.resolve("report").resolve("feedback").resolve(student.folder());
        assertThat(feedback.resolve("feedback.html")).exists();
        assertThat(feedback.resolve("1-tick1-diff.png")).exists();
        assertThat(feedback).isDirectoryNotContaining("glob:**/2-hidden*");
        assertThat(shared.resolve("report").resolve("index.html")).exists();
    }

    /** {@code words} with a capital first letter, as a list item of the feedback starts. */
    private static String capitalised(String words) {
        return Character.toUpperCase(words.charAt(0)) + words.substring(1);
    }

    static Stream<Variant> mistakes() {
        return Mistakes.onTheCoursesScenes().map(mistake -> (Variant) mistake.get()[0]);
    }

    @Test
    void everyMistakeOfTheCatalogueHasAStudentSolution() {
        assertThat(Stream.concat(mistakes(), Stream.of(Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT,
                Variant.ROOTS_ACCEPTED_AT_ZERO)))
                .containsExactlyInAnyOrder(Variant.seenInImages().stream().filter(v -> !v.isCorrect())
                        .toArray(Variant[]::new));
    }

    /**
     * A student's feedback.txt holds what {@code tick1 grade} prints for them alone, scene by
     * scene: the closest entry of the catalogue, what the methods' answers show and what to reread.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("mistakes")
    void aMistakeFailsWithItsDiagnosisOnThePublicSceneAndFixedWordsOnTheHiddenOne(Variant mistake) throws IOException {
        List<String> feedback = feedback(mistakesName(mistake));
        String text = String.join("\n", feedback);
        assertThat(row(mistakesName(mistake))).as(text).element(4).isEqualTo("0.00");
        assertThat(feedback).as(text).contains("tick1.xml: failed", "hidden scene 1: failed")
                .anyMatch(line -> line.startsWith("  FAILED: 2 of 2 scenes wrong."))
                .noneMatch(line -> line.contains(SubmissionGrader.CONGRATULATIONS));
        assertThat(feedback.stream().filter(line -> line.startsWith("  closest: "))).as(text).hasSize(1)
                .allMatch(line -> line.startsWith("  closest: " + mistake.title() + " (100.000% of pixels exact"));
        assertThat(feedback).as("the hidden scene: fixed words only\n" + text)
                .containsSubsequence("hidden scene 1: failed", "  " + HiddenVerdict.WRONG.words());
        // What to reread: the sections of the tested findings, or, for a mistake of render's that the answers of
        // intersectionWith and illuminate cannot show, the entry the image matches exactly.
        List<String> probes = feedback.stream().filter(line -> line.startsWith("  behaviour: ")).toList();
        List<String> reread = feedback.stream().filter(line -> line.startsWith("  reread: ")).toList();
        if (Mistakes.RENDER_ONLY.contains(mistake)) {
            assertThat(probes).as(text).isEmpty();
            String place = Variant.where(mistake.reread());
            assertThat(reread).as(text).anyMatch(line -> line.startsWith("  reread: " + place));
        } else {
            assertThat(probes).as(text).isNotEmpty();
            assertThat(probes).as(text).first().asString().contains("\"" + mistake.title() + "\"");
            // One wrong image carries the findings' lines; the other scene's diagnosis asks nothing to reread.
            assertThat(reread).as(text).isNotEmpty().hasSizeLessThanOrEqualTo(3);
        }
    }

    @Test
    void anInfiniteLoopIsStoppedAtTheTimeLimitAndReported() throws IOException {
        List<String> feedback = feedback("Loops Forever");
        assertThat(row("Loops Forever")).element(4).isEqualTo("0.00");
        assertThat(feedback).as(String.join("\n", feedback)).containsSubsequence("tick1.xml: failed",
                "  no image within the time limit of 20 s (an infinite loop?); the program was stopped",
                "hidden scene 1: failed", "  " + HiddenVerdict.TIME_LIMIT.words());
    }

    @Test
    void anExceptionIsReportedWithWhereTheStudentsCodeThrewIt() throws IOException {
        List<String> feedback = feedback("Throws");
        assertThat(feedback).as(String.join("\n", feedback))
                .anyMatch(line -> line.startsWith("  the code threw java.lang.NullPointerException"))
                .anyMatch(line -> line.startsWith("  at gfx.tick1.Renderer.illuminate(Renderer.java:"))
                .noneMatch(line -> line.contains("StudentHarness"));
    }

    @Test
    void codeThatUsesAMissingMethodIsReportedWithTheStudentsFile() throws IOException {
        assertThat(row("Missing Method")).element(9).asString()
                .contains("does not compile", "Renderer.java:", "error: cannot find symbol");
    }

    @Test
    void aUtf8ByteOrderMarkIsAccepted() throws IOException {
        assertThat(row("Byte Order")).as("both files begin with a byte order mark").element(4).isEqualTo("1.00");
    }

    /** Comment lines that overflowed the stack of a grader parsing the package by a regex. */
    @Test
    void aThousandSixHundredCommentLinesBeforeThePackageAreReadAsJavacReadsThem() throws IOException {
        List<String> feedback = feedback("Comment Flood");
        assertThat(row("Comment Flood")).as(String.join("\n", feedback)).element(4).isEqualTo("1.00");
        assertThat(feedback).noneMatch(line -> line.contains("Exception") || line.contains("\tat "));
    }

    /** A package line that never ends, which a grader parsing the package by a regex took quadratic time on. */
    @Test
    void aPackageLineThatNeverEndsIsRefusedByTheScanCap() throws IOException {
        assertThat(row("Endless Package")).element(9).asString()
                .contains("but it declares no package within its first 65536 characters");
    }

    @Test
    void theReportPageInABrowserCountsWhatGradesCsvSaysAndDrawsTheChart() throws Exception {
        HeadlessChromium.assumeInstalled();
        Path report = shared.resolve("report");
        Map<String, List<String>> rows = rows(report);
        long passed = rows.values().stream().filter(row -> row.get(4).equals("1.00")).count();
        try (HeadlessChromium browser = HeadlessChromium.start()) {
            browser.driver.get(report.resolve("index.html").toUri().toString());
            browser.waitUpTo(Duration.ofSeconds(60))
                    .until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-status", "ready"));
            assertThat(browser.driver.findElement(By.id("passed-count")).getText()).as("passed, as grades.csv says")
                    .isEqualTo(String.valueOf(passed));
            assertThat(browser.driver.findElement(By.id("total-count")).getText()).as("rows of grades.csv")
                    .isEqualTo(String.valueOf(rows.size()));
            assertThat(browser.driver.findElements(By.cssSelector("#diagnoses g.bar"))).as("the chart's bars")
                    .isNotEmpty();
        }
    }

    @Test
    void noFileAStudentIsGivenNamesAHiddenScene() throws IOException {
        Path report = shared.resolve("report");
        List<String> feedback = new ArrayList<>(rows(report).values().stream().map(row -> row.get(9)).toList());
        try (Stream<Path> files = Files.walk(report.resolve("feedback"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".txt") || f.toString().endsWith(".html"))
                    .toList()) {
                feedback.add(Files.readString(file));
            }
        }
        feedback.add(Files.readString(report.resolve("index.html")));
        assertThat(feedback).as("the gradebook's comments, the feedback files and the cohort's page")
                .noneMatch(text -> text.contains("hidden.xml"))
                .anyMatch(text -> text.contains("hidden scene 1: "));
    }

    @Test
    void aSecondRunGradesNothingAgainAndWritesTheSameGrades() throws IOException {
        Path report = shared.resolve("report");
        Map<String, List<String>> before = withoutGradingTime(rows(report));
        CliRun again = CliRun.of(gradeArguments(shared.resolve("download.zip"), report));
        assertThat(again.status()).as(again.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(again.out()).contains("(0 now, ");
        assertThat(withoutGradingTime(rows(report))).isEqualTo(before);
    }

    /**
     * The rows without their "Last modified (grade)" cell: a fresh worksheet says when it was
     * written, as Moodle wants to know when the grades it takes were made.
     */
    private static Map<String, List<String>> withoutGradingTime(Map<String, List<String>> rows) {
        int column = Worksheet.HEADER.indexOf("Last modified (grade)");
        Map<String, List<String>> without = new LinkedHashMap<>();
        rows.forEach((id, cells) -> {
            List<String> kept = new ArrayList<>(cells);
            kept.remove(column);
            without.put(id, kept);
        });
        return without;
    }

    @Test
    void aChangedSubmissionIsTheOnlyOneGradedAgain(@TempDir Path dir) throws IOException {
        // The cohort's report folder as its grade left it, and the download again with one failure mended.
        Path report = dir.resolve("report");
        GradeAttackTest.copyTree(shared.resolve("report"), report);
        Student failed = student(mistakesName(Variant.R_WRONG_WAY));
        Path feedback = report.resolve("feedback").resolve(failed.folder());
        assertThat(feedback.resolve("1-tick1-diff.png")).exists();
        Map<String, List<String>> before = withoutGradingTime(rows(report));
        List<Student> mended = cohort.stream().map(student -> student.id() != failed.id() ? student : new Student(
                failed.name(), failed.id(), files(StudentSolution.correct().editRenderer("return image;",
                "return image; // mended")), true)).toList();
        java.util.regex.Matcher first = java.util.regex.Pattern.compile("\\((\\d+) now, 0 from earlier runs")
                .matcher(firstRun.out());
        assertThat(first.find()).as(firstRun.transcript()).isTrue();

        // Without the look-alike check, which compares every pair of the cohort again and changes no grade.
        CliRun again = CliRun.of(gradeArguments(moodleZip(dir.resolve("mended.zip"), mended), report,
                "--no-lookalikes"));

        assertThat(again.out()).as(again.transcript())
                .contains("(1 now, " + (Integer.parseInt(first.group(1)) - 1) + " from earlier runs");
        Map<String, List<String>> after = withoutGradingTime(rows(report));
        assertThat(after.remove("Participant " + failed.id())).element(4).isEqualTo("1.00");
        before.remove("Participant " + failed.id());
        assertThat(after).as("every other row").isEqualTo(before);
        assertThat(feedback).as("the images of a failure since mended").isDirectoryNotContaining("glob:**.png");
    }

    @Test
    void aGradeKilledMidRunKeepsEveryFinishedResultWholeAndTheNextRunFinishesIt(@TempDir Path dir) throws Exception {
        StudentSolution correct = StudentSolution.correct();
        List<Student> students = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            students.add(new Student("Student " + i, 100 + i, files(correct.editRenderer("return image;",
                    "return image; // " + i)), true));
        }
        Path zip = moodleZip(dir.resolve("download.zip"), students);
        Path report = dir.resolve("report");
        Process grade = gradeInAJvmOfItsOwn(dir, gradeArguments(zip, report, "--jobs", "1"));
        // Wait (at most two minutes) for the first result to be stored, then pull the plug.
        Path state = report.resolve(CohortCommand.STATE_FOLDER);
        for (int i = 0; i < 1200 && storedResults(state).isEmpty() && grade.isAlive(); i++) {
            Thread.sleep(100);
        }
        grade.destroyForcibly().waitFor();
        // What a grader killed with SIGKILL leaves behind (docs/grading.md): its work folder, and its job's
        // compiler's tmpfs mounted there, which course staff unmount and delete.
        assertThat(WorkFolder.delete(dir.resolve("tmp"))).as("what the killed grade left behind, removed").isNull();
        int kept = storedResults(state).size();
        assertThat(kept).as(Files.readString(dir.resolve("grade.log"))).isBetween(1, students.size() - 1);
        assertThat(report.resolve("grades.csv")).as("no grades.csv before the end").doesNotExist();

        CliRun again = CliRun.of(gradeArguments(zip, report));
        assertThat(again.status()).as(again.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(again.out()).contains("(" + (students.size() - kept) + " now, " + kept + " from earlier runs)");
        assertThat(rows(report).values()).hasSize(students.size()).extracting(row -> row.get(4)).containsOnly("1.00");
        try (Stream<Path> left = Files.list(state)) {
            assertThat(left.map(p -> p.getFileName().toString())).as("half-written results")
                    .noneMatch(name -> name.startsWith("."));
        }
    }

    @Test
    void sigtermStopsTheGradeStoresNothingItCutShortAndLeavesNoWorkFolder(@TempDir Path dir) throws Exception {
        List<Student> looping = List.of(new Student("Loops", 1, files(StudentSolution.correct().editSphere(NEAR_ROOT,
                NEAR_ROOT + " while (s > 0) { }")), false));
        Path report = dir.resolve("report");
        Process grade = gradeInAJvmOfItsOwn(dir, gradeArguments(moodleZip(dir.resolve("a.zip"), looping), report,
                "--time-limit", "600"));
        // Wait (at most two minutes) for the student's code to be running.
        for (int i = 0; i < 1200 && grade.isAlive() && grade.descendants().noneMatch(p -> p.info().commandLine()
                .orElse("").contains("StudentHarness render")); i++) {
            Thread.sleep(100);
        }
        assertThat(grade.descendants().map(p -> p.info().commandLine().orElse("")))
                .as("the student's code is running: " + Files.readString(dir.resolve("grade.log")))
                .anyMatch(line -> line.contains("StudentHarness render"));
        List<ProcessHandle> running = grade.descendants().toList();
        grade.destroy();   // SIGTERM
        assertThat(grade.waitFor(60, TimeUnit.SECONDS)).as("the grade ended").isTrue();
        assertThat(Files.readString(dir.resolve("grade.log"))).as("what the stopped grade said")
                .doesNotContain("internal error", "Exception");
        for (ProcessHandle process : running) {
            process.onExit().get(30, TimeUnit.SECONDS);
        }
        assertThat(storedResults(report.resolve(CohortCommand.STATE_FOLDER))).as("results of a grade cut short")
                .isEmpty();
        assertThat(report.resolve("grades.csv")).as("a gradebook without the students not yet graded")
                .doesNotExist();
        try (Stream<Path> left = Files.list(dir.resolve("tmp"))) {
            assertThat(left).as("work folders").isEmpty();
        }
    }

    /**
     * Starts {@code tick1 ARGS} in a JVM of its own, printing into {@code dir}/grade.log, with
     * {@code dir}/tmp as its temporary folder (where its work folder goes; made if need be), which the
     * sandbox's users can pass through.
     */
    static Process gradeInAJvmOfItsOwn(Path dir, String... args) throws IOException {
        return gradeInAJvmOfItsOwn(dir, List.of(), args);
    }

    /** As {@link #gradeInAJvmOfItsOwn(Path, String...)}, in a JVM also given {@code jvmOptions}. */
    static Process gradeInAJvmOfItsOwn(Path dir, List<String> jvmOptions, String... args) throws IOException {
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx--x--x"));
        Path temporary = Files.isDirectory(dir.resolve("tmp")) ? dir.resolve("tmp") : Files.createDirectory(
                dir.resolve("tmp"), PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx--x--x")));
        List<String> command = CliRun.java();
        command.addAll(jvmOptions);
        // The class path's folders, not Tick1Jvm's jar: a grade stopped here is resumed in the tests' own JVM, and
        // a stored result is another build's (graded again) unless the code it was graded by is the same files.
        command.addAll(List.of("-Djava.io.tmpdir=" + temporary, "-cp", System.getProperty("java.class.path"),
                Tick1.class.getName()));
        command.addAll(List.of(args));
        return new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(dir.resolve("grade.log").toFile())
                .start();
    }

    /** The results a grade has stored: each a folder named by its key, whole. */
    private static List<Path> storedResults(Path state) throws IOException {
        if (!Files.isDirectory(state)) {
            return List.of();
        }
        try (Stream<Path> entries = Files.list(state)) {
            return entries.filter(p -> !p.getFileName().toString().startsWith(".")
                    && !p.getFileName().toString().equals(StoredCode.FOLDER)).toList();
        }
    }

    /**
     * The cohort marked per scene out of 10: its results, which hold every scene's verdict whatever the marking, are
     * marked again from its report folder (a copy), as course staff mark a graded cohort another way.
     */
    @Test
    void perSceneGradesAreTheShareOfScenesPassedTimesTheMaximum(@TempDir Path dir) throws IOException {
        Path report = dir.resolve("report");
        GradeAttackTest.copyTree(shared.resolve("report"), report);
        CliRun run = CliRun.of(gradeArguments(shared.resolve("download.zip"), report, "--per-scene", "--max-grade",
                "10", "--no-lookalikes"));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        Map<String, List<String>> rows = rows(report);
        List<String> right = rows.get("Participant " + student("Correct Student 0").id());
        assertThat(right).element(4).isEqualTo("10.00");
        assertThat(rows.get("Participant " + student(mistakesName(Variant.FAR_ROOT)).id())).element(4)
                .isEqualTo("0.00");
        assertThat(right).element(5).isEqualTo("10.00");
    }

    /**
     * A method whose blocks nest thousands deep, in a grader of small heap: its text for the look-alike check would
     * grow as the square of the depth. It is not compared, and every student is graded and the report written.
     */
    @Test
    void codeNestedThousandsDeepCostsNoOneTheirGradeNorTheReport(@TempDir Path dir) throws Exception {
        StudentSolution correct = StudentSolution.correct();
        String deep = "void deep() " + "{".repeat(3_500) + "}".repeat(3_500) + "\n    ";
        List<Student> two = List.of(new Student("Right", 1, files(correct), true),
                new Student("Nested", 2, files(correct.editSphere("public Vector3 getColour()",
                        deep + "public Vector3 getColour()")), false));
        Path report = dir.resolve("report");
        Process grade = gradeInAJvmOfItsOwn(dir, List.of("-Xmx160m"), gradeArguments(moodleZip(dir.resolve("a.zip"),
                two), report));
        assertThat(grade.waitFor(5, TimeUnit.MINUTES)).as("the grade ended").isTrue();
        String log = Files.readString(dir.resolve("grade.log"));
        assertThat(log).as("what the grade said").doesNotContain("out of memory", "internal error", "Exception");
        assertThat(rows(report)).as(log).containsOnlyKeys("Participant 1", "Participant 2");
        assertThat(rows(report).get("Participant 1")).as(log).element(4).isEqualTo("1.00");
        assertThat(report.resolve("index.html")).as(log).isRegularFile();
    }

    @Test
    void aDownloadThatIsNotThereIsOneLineAndExitTwo(@TempDir Path dir) {
        CliRun run = CliRun.of(gradeArguments(dir.resolve("nope.zip"), dir.resolve("report")));
        assertThat(run.status()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).singleElement().asString().startsWith("tick1 grade: ")
                .contains("nope.zip");
    }

    @Test
    void cohortOptionsWithOneStudentAreRefused(@TempDir Path dir) throws IOException {
        Path[] files = StudentSolution.correct().writeTo(dir);
        CliRun run = CliRun.of("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--jobs", "2");
        assertThat(run.status()).isEqualTo(GradeCommand.EXIT_USAGE);
        // picocli's argument groups say it: the cohort's options need --submissions.
        assertThat(run.err().lines()).singleElement().asString()
                .contains("Missing required argument(s): --submissions=PATH");
    }

    static final String WORKSHEET_HEADER = String.join(",", Worksheet.HEADER);

    static String worksheetRow(int id, String name, String maximum) {
        return "Participant " + id + "," + name + ",,Submitted for grading,," + maximum + ",Yes,,,\r\n";
    }

    @Test
    void aBadWorksheetStopsTheGradeBeforeAnythingIsGradedOrWritten(@TempDir Path dir) throws IOException {
        Path download = moodleZip(dir.resolve("a.zip"), List.of(new Student("Right", 1,
                files(StudentSolution.correct()), true)));
        Path report = dir.resolve("report");
        CliRun run = CliRun.of(gradeArguments(download, report, "--worksheet", download.toString()));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).singleElement().asString()
                .startsWith("tick1 grade: " + download + ": a zip archive, not a worksheet");
        assertThat(report).doesNotExist();
    }

    @Test
    void aMaxGradeOtherThanTheWorksheetsIsOneLineBeforeAnythingIsGraded(@TempDir Path dir) throws IOException {
        Path download = moodleZip(dir.resolve("a.zip"), List.of(new Student("Right", 1,
                files(StudentSolution.correct()), true)));
        Path worksheet = Files.writeString(dir.resolve("w.csv"), WORKSHEET_HEADER + "\r\n"
                + worksheetRow(1, "Right", "10.00"));
        Path report = dir.resolve("report");
        CliRun run = CliRun.of(gradeArguments(download, report, "--worksheet", worksheet.toString(),
                "--max-grade", "1"));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err()).isEqualTo("tick1 grade: --max-grade 1.00 differs from the Maximum Grade 10.00 of "
                + worksheet + ": leave --max-grade out to grade out of 10.00, or change the assignment's maximum "
                + "in Moodle first" + System.lineSeparator());
        assertThat(report).doesNotExist();
    }

    @Test
    void theWorksheetsMaximumIsTheDefaultAndAParticipantInTwoFoldersIsOneLineAndABlankFailingRow(@TempDir Path dir)
            throws IOException {
        StudentSolution correct = StudentSolution.correct();
        Path download = moodleZip(dir.resolve("a.zip"), List.of(new Student("Right", 1, files(correct), true),
                new Student("Twin", 5, files(correct), false), new Student("Twin Again", 5, files(correct), false)));
        Path worksheet = Files.writeString(dir.resolve("w.csv"), WORKSHEET_HEADER + "\r\n"
                + worksheetRow(1, "Right", "10.00") + worksheetRow(5, "Twin", "10.00"));
        Path report = dir.resolve("report");
        CliRun run = CliRun.of(gradeArguments(download, report, "--worksheet", worksheet.toString()));
        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_PASS);
        assertThat(run.err().lines().filter(line -> line.contains("participant 5"))).singleElement().asString()
                .contains("Twin Again_5_assignsubmission_file_", "Twin_5_assignsubmission_file_");
        Map<String, List<String>> rows = rows(report);
        assertThat(rows.get("Participant 1")).element(4).isEqualTo("10.00");
        assertThat(rows.get("Participant 5")).element(4).isEqualTo("");
        assertThat(rows.get("Participant 5")).element(9).asString().contains("two folders");
        assertThat(Files.readString(report.resolve("index.html"))).contains("Twin Again", "Twin<");
    }
}
