package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.grade.MoodleNaming;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.engine.image.ImageDifference;
import java.io.IOException;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The report's files as text: what they say, what they link to, and what they must never hold. */
class CohortReportTest {

    private static final Pattern LINK = Pattern.compile("\\b(?:href|src)=\"([^\"]*)\"");

    @TempDir
    Path report;

    private List<StudentResult> results;

    @BeforeEach
    void writeTheReport() throws IOException {
        results = SmallCohort.writeImages(report);
        CohortReport.write(report, results, SmallCohort::grade);
    }

    private String read(Path file) throws IOException {
        return Files.readString(file, StandardCharsets.UTF_8);
    }

    private String index() throws IOException {
        return read(report.resolve(CohortReport.INDEX));
    }

    private Path feedbackFolder(StudentResult result) {
        return report.resolve("feedback").resolve(result.submission().folder());
    }

    private List<Path> pages() throws IOException {
        try (Stream<Path> files = Files.walk(report)) {
            return files.filter(file -> file.toString().endsWith(".html")).sorted().toList();
        }
    }

    @Test
    void everyStudentGetsAFeedbackPageAndAPlainTextCopyInTheirFolder() {
        for (StudentResult result : results) {
            String folder = result.submission().folder();
            assertThat(feedbackFolder(result).resolve("feedback.html")).as(folder).isRegularFile();
            assertThat(feedbackFolder(result).resolve("feedback.txt")).as(folder).isRegularFile();
        }
    }

    @Test
    void theIndexCountsThePassesOfTheWholeCohort() throws IOException {
        long passed = results.stream().filter(StudentResult::passed).count();
        assertThat(index()).contains("<strong id=\"passed-count\">" + passed + "</strong> of "
                + "<strong id=\"total-count\">" + results.size() + "</strong> passed");
    }

    @Test
    void theIndexHasOneRowPerStudentWithTheirGradeAndTime() throws IOException {
        String index = index();
        assertThat(index.split("<tr class=\"(?:pass|fail)\">", -1)).hasSize(results.size() + 1);
        for (StudentResult result : results) {
            assertThat(index).contains("<td class=\"time\" data-sort=\"" + result.time().toMillis() + "\">"
                    + CohortPage.duration(result.time()) + "</td>");
        }
        assertThat(index).contains("<td data-sort=\"1.00\">1.00</td>", "<td data-sort=\"0.00\">0.00</td>");
    }

    @Test
    void theChartHasOneBarPerDiagnosisOfAFailureWithItsCountMostCommonFirst() throws IOException {
        Map<String, Long> expected = results.stream().filter(result -> !result.passed())
                .collect(Collectors.groupingBy(result -> result.diagnosis().label(), TreeMap::new,
                        Collectors.counting()));
        Matcher bar = Pattern.compile("<g class=\"bar\" data-label=\"([^\"]*)\" data-count=\"(\\d+)\">")
                .matcher(index());
        Map<String, Long> drawn = new TreeMap<>();
        List<Long> order = new ArrayList<>();
        while (bar.find()) {
            drawn.put(bar.group(1), Long.parseLong(bar.group(2)));
            order.add(Long.parseLong(bar.group(2)));
        }
        assertThat(drawn).isEqualTo(expected);
        assertThat(order).isSortedAccordingTo((a, b) -> Long.compare(b, a));
    }

    @Test
    void anEmptyCohortStillGetsAnIndexAndAnEmptyZip() throws IOException {
        CohortReport.write(report, List.of(), SmallCohort::grade);
        assertThat(index()).contains("<strong id=\"passed-count\">0</strong> of <strong id=\"total-count\">0</strong>",
                "No submission failed.");
        assertThat(zipEntries()).isEmpty();
    }

    @Test
    void aCohortWithNoFailureSaysSoInsteadOfAnEmptyChart() throws IOException {
        CohortReport.write(report, List.of(results.get(0)), SmallCohort::grade);
        assertThat(index()).contains("No submission failed.").doesNotContain("class=\"bar\"");
    }

    @Test
    void markupInANameAFolderOrAReasonIsShownAsText() throws IOException {
        for (Path page : pages()) {
            assertThat(read(page)).as(page.toString())
                    .doesNotContain("<img src=x", "<script>window", "<b>tick1.xml</b>", "onerror=\"window")
                    .doesNotContain(SmallCohort.HOSTILE_NAME);
        }
        assertThat(index()).contains("&lt;img src=x onerror=&quot;window.xssRan=1&quot;&gt;Mallory",
                "&lt;b&gt;tick1.xml&lt;/b&gt; &amp; &quot;friends&quot;");
    }

    @Test
    void controlCharactersInANameNeverReachAPageOrTheTextFile() throws IOException {
        Submission bell = new Submission("Eve_1005_assignsubmission_file_", "1005", "Eve\u001b[2J\u0007\u202Eevil",
                null, null, null);
        StudentResult result = new StudentResult(bell, new StudentResult.Summary(false, 0, 0,
                Category.Outcome.SUBMISSION_PROBLEM, "No Sphere.java."), List.of(), Duration.ofMillis(10));
        CohortReport.write(report, List.of(result), SmallCohort::grade);
        assertThat(index() + read(feedbackFolder(result).resolve("feedback.html"))
                + read(feedbackFolder(result).resolve("feedback.txt"))).doesNotContain("\u001b", "\u0007");
        assertThat(read(feedbackFolder(result).resolve("feedback.txt"))).doesNotContain("\u202E");
        assertThat(index()).contains("<bdi>Eve\uFFFD[2J\uFFFD\u202Eevil</bdi>");
    }

    @Test
    void theIndexLinksTheFeedbackZipAndTheGradebookWhenItIsThere() throws IOException {
        assertThat(index()).contains("<a href=\"feedback.zip\">").doesNotContain("grades.csv");
        Files.writeString(report.resolve("grades.csv"), "Identifier,Full name\n");
        CohortReport.write(report, results, SmallCohort::grade);
        assertThat(index()).contains("<a href=\"feedback.zip\">", "<a href=\"grades.csv\">");
    }

    @Test
    void thePagesMayBeReadByWhoeverMayReadAnyNewFileOfTheFolder() throws IOException {
        Path ordinary = Files.writeString(report.resolve("ordinary.txt"), "made as any file is");
        Set<PosixFilePermission> expected = Files.getPosixFilePermissions(ordinary);
        for (Path page : pages()) {
            assertThat(Files.getPosixFilePermissions(page)).as(page.toString()).isEqualTo(expected);
        }
    }

    @Test
    void everyLinkIsRelativeAndNamesAFileInsideTheReportFolder() throws IOException {
        Path root = report.toRealPath();
        int links = 0;
        for (Path page : pages()) {
            Matcher link = LINK.matcher(read(page));
            while (link.find()) {
                links++;
                String url = link.group(1).replace("&amp;", "&");
                assertThat(url).as(page + ": " + url).doesNotContain(":", "?", "#", "\\").doesNotStartWith("/");
                Path target = page.getParent().resolve(URLDecoder.decode(url, StandardCharsets.UTF_8)).normalize();
                assertThat(target).as(page + ": " + url).isRegularFile();
                assertThat(target.toRealPath()).as(page + ": " + url).startsWith(root);
            }
        }
        assertThat(links).as("links in the pages").isGreaterThan(results.size());
    }

    @Test
    void noPageNamesAnythingOutsideTheReportFolder() throws IOException {
        for (Path page : pages()) {
            assertThat(read(page)).as(page.toString()).doesNotContainIgnoringCase("http:")
                    .doesNotContainIgnoringCase("https:").doesNotContainIgnoringCase("file:")
                    .doesNotContain("url(", "@import", "=\"//");
        }
    }

    @Test
    void theIndexLoadsItsThumbnailsLazily() throws IOException {
        Matcher image = Pattern.compile("<img [^>]*>").matcher(index());
        int thumbnails = 0;
        while (image.find()) {
            thumbnails++;
            assertThat(image.group()).contains("loading=\"lazy\"");
        }
        long publicHeatMaps = results.stream().flatMap(result -> result.scenes().stream())
                .filter(scene -> !scene.hidden() && scene.files().heatMap() != null).count();
        assertThat(thumbnails).isEqualTo(publicHeatMaps).isPositive();
    }

    @Test
    void aHiddenScenesNameAndImagesAreNeverShownOrReturned() throws IOException {
        for (Path page : pages()) {
            assertThat(read(page)).as(page.toString()).doesNotContain(SmallCohort.HIDDEN_NAME, "secret",
                    SmallCohort.HIDDEN_HEAT_MAP);
        }
        StudentResult hiddenFails = results.get(3);
        String text = read(feedbackFolder(hiddenFails).resolve("feedback.txt"));
        assertThat(text).contains("hidden scene 1: failed", "4 of 192 pixels differ").doesNotContain("secret");
        assertThat(zipEntries()).noneMatch(entry -> entry.contains("secret"));
    }

    @Test
    void aFailingPublicSceneShowsItsThreeImagesAndTheLegendOfTheHeatMapColours() throws IOException {
        String page = read(feedbackFolder(results.get(1)).resolve("feedback.html"));
        assertThat(page).contains("src=\"1-tick1-diff.png\"", "src=\"1-tick1-yours.png\"",
                "src=\"1-tick1-expected.png\"");
        for (int levels : new int[] {1, 2, 4, 8, 16, 32, 64}) {
            assertThat(page).contains(String.format("background:#%06x", ImageDifference.heatColour(levels)));
        }
        assertThat(read(feedbackFolder(results.get(0)).resolve("feedback.html"))).as("a pass has no heat map")
                .doesNotContain("<img", "Heat map colours");
    }

    @Test
    void anImageTheGraderCouldNotWriteIsLeftOutOfThePagesAndTheZip() throws IOException {
        Files.delete(feedbackFolder(results.get(1)).resolve("1-tick1-expected.png"));
        CohortReport.write(report, results, SmallCohort::grade);
        String page = read(feedbackFolder(results.get(1)).resolve("feedback.html"));
        assertThat(page).contains("src=\"1-tick1-diff.png\"").doesNotContain("1-tick1-expected.png");
        assertThat(zipEntries()).noneMatch(entry -> entry.endsWith("/1-tick1-expected.png")
                && entry.startsWith(results.get(1).submission().folder()));
    }

    @Test
    void whatToRereadIsGatheredOnceAtTheTopOfTheFeedback() throws IOException {
        String page = read(feedbackFolder(results.get(3)).resolve("feedback.html"));
        String reread = "Handout section 3.2, &quot;Diffuse reflection&quot;.";
        assertThat(page).contains("<h2>What to reread</h2>\n<ul class=\"reread\">\n<li>" + reread + "</li>\n</ul>");
        assertThat(page.indexOf("What to reread")).isLessThan(page.indexOf("<h2>Scenes</h2>"));
        assertThat(read(feedbackFolder(results.get(2)).resolve("feedback.html"))).doesNotContain("What to reread");
    }

    @Test
    void feedbackTellsWhatPassedAndWhatFailed() throws IOException {
        String text = read(feedbackFolder(results.get(1)).resolve("feedback.txt"));
        assertThat(text).contains("Result: not passed: 1 of 2 scenes matched",
                "What to reread\n  - Handout section 3.2", "tick1.xml: failed",
                "hidden scene 1: passed", "images beside this file: 1-tick1-diff.png, 1-tick1-yours.png");
        assertThat(read(feedbackFolder(results.get(0)).resolve("feedback.txt"))).contains("Result: passed");
    }

    private List<String> zipEntries() throws IOException {
        return SmallCohort.zipEntries(report);
    }

    @Test
    void theZipHoldsEachStudentsFeedbackInAFolderNamedAsInTheDownload() throws IOException {
        List<String> expected = new ArrayList<>();
        for (StudentResult result : results) {
            String folder = result.submission().folder();
            expected.add(folder + "/feedback.html");
            expected.add(folder + "/feedback.txt");
            for (SceneResult scene : result.scenes()) {
                if (!scene.hidden() && scene.files().heatMap() != null) {
                    scene.files().named().forEach(image -> expected.add(folder + "/" + image));
                }
            }
        }
        assertThat(zipEntries()).containsExactlyElementsOf(expected);
    }

    @Test
    void aFolderNameThatWouldLeaveTheReportFolderIsRefusedBeforeAnythingIsWritten() throws IOException {
        Path elsewhere = report.resolve("elsewhere");
        for (String folder : new String[] {"../escape", "..", ".", "", "a/b", "a\\b"}) {
            Submission sneaky = new Submission(folder, "1", "Sneaky", null, null, null);
            StudentResult result = new StudentResult(sneaky, new StudentResult.Summary(true, 1, 1,
                    Category.Outcome.PASSED, "fine"), List.of(), Duration.ZERO);
            assertThatThrownBy(() -> CohortReport.write(elsewhere, List.of(result), SmallCohort::grade))
                    .as(folder).isInstanceOf(IllegalArgumentException.class);
        }
        assertThat(elsewhere).doesNotExist();
        assertThat(report.getParent().resolve("escape")).doesNotExist();
    }

    @Test
    void twoResultsForOneFolderAreRefused() {
        assertThatThrownBy(() -> CohortReport.write(report, List.of(results.get(0), results.get(0)),
                SmallCohort::grade)).isInstanceOf(IllegalArgumentException.class).hasMessageContaining("share");
    }

    @Test
    void writingLeavesNoTemporaryFileBehind() throws IOException {
        CohortReport.write(report, results, SmallCohort::grade);
        try (Stream<Path> files = Files.walk(report)) {
            assertThat(files.map(Path::getFileName).map(Path::toString)).noneMatch(name -> name.endsWith(".tmp"));
        }
    }

    @Test
    void aWriteThatFailsPartWayLeavesTheEarlierFileWhole() throws IOException {
        Path index = report.resolve(CohortReport.INDEX);
        String before = read(index);
        assertThatThrownBy(() -> ReportFiles.write(index, out -> {
            out.write("<!DOCTYPE html><p>half".getBytes(StandardCharsets.UTF_8));
            throw new IOException("No space left on device");
        })).hasMessage("No space left on device");
        assertThat(read(index)).isEqualTo(before);
        try (Stream<Path> files = Files.list(report)) {
            assertThat(files.map(Path::getFileName).map(Path::toString)).noneMatch(name -> name.endsWith(".tmp"));
        }
    }

    @Test
    void timesReadAtAGlance() {
        assertThat(CohortPage.duration(Duration.ofMillis(850))).isEqualTo("850 ms");
        assertThat(CohortPage.duration(Duration.ofMillis(4200))).isEqualTo("4.2 s");
        assertThat(CohortPage.duration(Duration.ofMillis(61_000))).isEqualTo("1 min 01 s");
    }

    @Test
    void theReasonColumnIsShortWithoutTheTerminalsPaddingAndTheWholeReasonInItsTitle() throws IOException {
        String reason = "FAILED: tick1.xml: ( 67.838% of pixels exact,  99.1% within 1 level) " + "word ".repeat(200);
        Submission wordy = new Submission("Lee_1006_assignsubmission_file_", "1006", "Lee", null, null, null);
        StudentResult result = new StudentResult(wordy, new StudentResult.Summary(false, 0, 1,
                Category.Outcome.UNRECOGNISED, reason), List.of(), Duration.ofMillis(10));
        CohortReport.write(report, List.of(result), SmallCohort::grade);

        Matcher cell = Pattern.compile("<td class=\"reason\" title=\"([^\"]*)\">([^<]*)</td>").matcher(index());
        assertThat(cell.find()).as("a reason cell").isTrue();
        assertThat(cell.group(2)).startsWith("FAILED: tick1.xml: (67.838% of pixels exact, 99.1% within")
                .endsWith("\u2026").hasSizeLessThanOrEqualTo(CellText.MAX_SHORT);
        assertThat(cell.group(1)).doesNotContain("  ", "( ").endsWith("word");
    }

    @Test
    void thumbnailsAreLargeEnoughToSeeAMistake() throws IOException {
        Matcher thumbnail = Pattern.compile("<img class=\"thumbnail\"[^>]* width=\"(\\d+)\"").matcher(index());
        assertThat(thumbnail.find()).as("a thumbnail").isTrue();
        assertThat(Integer.parseInt(thumbnail.group(1))).isGreaterThanOrEqualTo(160);
    }

    @Test
    void everyTextOfAResultIsBoundedBeforeTheReportWritesIt() {
        String huge = "Sphere.java and ".repeat(1_000_000);
        Submission big = new Submission("x_1_assignsubmission_file_", huge, huge, null, null, huge);
        StudentResult result = new StudentResult(big, new StudentResult.Summary(false, 0, 1,
                new Category.Mistake(huge), huge), List.of(new StudentResult.SceneResult(huge, false, false,
                java.util.Collections.nCopies(20_000, huge), StudentResult.SceneResult.Images.NONE)), Duration.ZERO);

        StudentResult bounded = CohortOutputs.forReport(List.of(result)).get(0);

        assertThat(bounded.reason()).hasSizeLessThanOrEqualTo(CohortOutputs.MAX_REASON);
        assertThat(bounded.submission().fullName()).hasSizeLessThanOrEqualTo(CohortOutputs.MAX_NAME);
        assertThat(bounded.submission().id()).hasSizeLessThanOrEqualTo(CohortOutputs.MAX_NAME);
        assertThat(bounded.diagnosis().label()).hasSizeLessThanOrEqualTo(CohortOutputs.MAX_NAME);
        assertThat(bounded.scenes().get(0).explanation()).hasSizeLessThanOrEqualTo(CohortOutputs.MAX_LINES + 1)
                .allSatisfy(line -> assertThat(line).hasSizeLessThanOrEqualTo(CohortOutputs.MAX_LINE));
    }

    @Test
    void aC1ControlOrABidiMarkInAFolderNameBecomesASpaceInTheFeedbackFolderAndTheZip() throws IOException {
        // Moodle's clean_filename leaves both in a full name; an _ in their place would hide the id from its importer.
        Submission csi = new Submission("Eve\u009b2J\u202e_1007_assignsubmission_file_", "1007", "Eve", null, null,
                "no Sphere.java in the submission");
        StudentResult result = new StudentResult(csi, new StudentResult.Summary(false, 0, 0,
                Category.Outcome.SUBMISSION_PROBLEM, "FAILED"), List.of(), Duration.ZERO);

        List<StudentResult> plain = CohortOutputs.forReport(List.of(result));
        CohortReport.write(report, plain, SmallCohort::grade);

        assertThat(plain.get(0).submission().folder()).isEqualTo("Eve 2J _1007_assignsubmission_file_");
        assertThat(MoodleNaming.importerParticipant(plain.get(0).submission().folder()))
                .as("the participant Moodle's importer reads").isEqualTo(1007);
        assertThat(report.resolve("feedback").resolve("Eve 2J _1007_assignsubmission_file_")).isDirectory();
        try (ZipInputStream zip = new ZipInputStream(Files.newInputStream(report.resolve("feedback.zip")))) {
            for (ZipEntry entry = zip.getNextEntry(); entry != null; entry = zip.getNextEntry()) {
                assertThat(entry.getName()).doesNotContain("\u009b", "\u202e");
            }
        }
    }
}
