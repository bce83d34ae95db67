package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.PngOutput;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;

/**
 * A cohort of six made by hand, as the grader would leave it: results, and for each failing public
 * scene three small PNGs in the student's feedback folder. It holds what the report must survive:
 * markup in a name, a folder and a reason; non-ASCII names; a folder that is not Moodle's; a
 * submission that ran nothing; and a hidden scene whose name and heat-map name must never show.
 */
final class SmallCohort {

    /** A name that runs script if it is ever written into a page unescaped. */
    static final String HOSTILE_NAME = "<img src=x onerror=\"window.xssRan=1\">Mallory</td></tr><script>"
            + "window.xssRan=2</script>";
    static final String HOSTILE_FOLDER = "<img src=x onerror=window.xssRan=3> & \"Co\" #1?_1002_assignsubmission_file_";
    static final String HIDDEN_NAME = "secret-giant-floor.xml";
    static final String HIDDEN_HEAT_MAP = "2-secret-giant-floor-diff.png";
    static final String NOT_CLAMPED = "N.L not clamped (Figure 6b)";

    private SmallCohort() {
    }

    /** Writes the images into {@code report}'s feedback folders and returns the results. */
    static List<StudentResult> writeImages(Path report) throws IOException {
        List<StudentResult> results = new ArrayList<>();
        results.add(passed("Ada Lovelace_1001_assignsubmission_file_", "1001", "Ada Lovelace", 1200));
        results.add(failedOnTick1(report, HOSTILE_FOLDER, "1002", HOSTILE_NAME, NOT_CLAMPED, 4200,
                "1 of 2 scenes wrong: <b>tick1.xml</b> & \"friends\"", false));
        results.add(new StudentResult(new Submission("Bob Jones_1003_assignsubmission_file_", "1003", "Bob Jones",
                null, null, null), new StudentResult.Summary(false, 0, 0, Category.Outcome.DOES_NOT_COMPILE,
                        "The code does not compile: "
                + "Sphere.java:12:5: error: ';' expected"), List.of(), Duration.ofMillis(2500)));
        results.add(failedOnTick1(report, "José Ñúñez 陈伟_1004_assignsubmission_file_", "1004",
                "José Ñúñez 陈伟", NOT_CLAMPED, 61_000, "2 of 2 scenes wrong.", true));
        results.add(new StudentResult(new Submission("crsid42", "crsid42", "crsid42", null, null, null),
                new StudentResult.Summary(false, 0, 2, Category.Outcome.TIME_LIMIT,
                "The code ran out of time (60 s) before it finished tick1.xml."), List.of(scene("tick1.xml", false,
                false, List.of("not rendered: the time limit"), null, null, null),
                        scene(HIDDEN_NAME, true, false, List.of("not rendered: the time limit"), null, null, null)),
                                Duration.ofSeconds(60)));
        results.add(passed("Zoë Brown_999_assignsubmission_file_", "999", "Zoë Brown", 850));
        return results;
    }

    /**
     * A cohort of {@code size} failing students, each with the three images of a failing tick1.xml,
     * their times spread over a minute: the size of a year's class, to see the index stay usable.
     */
    static List<StudentResult> large(Path report, int size) throws IOException {
        List<StudentResult> results = new ArrayList<>();
        StudentResult model = failedOnTick1(report, "model", "0", "Model", NOT_CLAMPED, 0, "wrong", false);
        Path modelFolder = report.resolve("feedback").resolve("model");
        for (int i = 1; i <= size; i++) {
            String folder = "Student " + i + "_" + (5000 + i) + "_assignsubmission_file_";
            Path feedback = Files.createDirectories(report.resolve("feedback").resolve(folder));
            for (String image : new String[] {"1-tick1-diff.png", "1-tick1-yours.png", "1-tick1-expected.png"}) {
                Files.copy(modelFolder.resolve(image), feedback.resolve(image));
            }
            results.add(new StudentResult(new Submission(folder, String.valueOf(5000 + i), "Student " + i, null, null,
                    null), new StudentResult.Summary(false, 1, 2,
                            i % 3 == 0 ? Category.Outcome.TIME_LIMIT : new Category.Mistake(NOT_CLAMPED),
                            "1 of 2 scenes wrong."), model.scenes(), Duration.ofMillis(i * 7919L % 60_000)));
        }
        return results;
    }

    private static StudentResult passed(String folder, String id, String name, long millis) {
        return new StudentResult(new Submission(folder, id, name, null, null, null), new StudentResult.Summary(true, 2,
                2, Category.Outcome.PASSED, "Congratulations! Your code passed the tester."),
                List.of(scene("tick1.xml", false, true, List.of(), null, null, null),
                        scene(HIDDEN_NAME, true, true, List.of(), null, null, null)), Duration.ofMillis(millis));
    }

    private static StudentResult failedOnTick1(Path report, String folder, String id, String name, String diagnosis,
            long millis, String reason, boolean hiddenFails) throws IOException {
        Path feedback = Files.createDirectories(report.resolve("feedback").resolve(folder));
        BufferedImage expected = image(0x204060);
        BufferedImage yours = image(0x1f4070);
        PngOutput.write(ImageDifference.between(expected, yours).heatMap(), feedback.resolve("1-tick1-diff.png"));
        PngOutput.write(yours, feedback.resolve("1-tick1-yours.png"));
        PngOutput.write(expected, feedback.resolve("1-tick1-expected.png"));
        List<String> explanation = List.of("96 of 192 pixels differ (50.000%), max difference 16 levels",
                "closest: " + diagnosis + " (50% equal)", "verdict: " + diagnosis + ": every pixel matches it exactly.",
                "likely cause: N.L is not clamped at 0 <for the back of a sphere>.",
                "reread: handout section 3.2, \"Diffuse reflection\".");
        List<SceneResult> scenes = new ArrayList<>();
        scenes.add(scene("tick1.xml", false, false, explanation, "1-tick1-diff.png", "1-tick1-yours.png",
                "1-tick1-expected.png"));
        // A hidden scene's heat map named here must still never be shown or returned.
        Files.write(feedback.resolve(HIDDEN_HEAT_MAP), Files.readAllBytes(feedback.resolve("1-tick1-diff.png")));
        scenes.add(hiddenFails ? scene(HIDDEN_NAME, true, false, List.of("4 of 192 pixels differ",
                "reread: handout section 3.2, \"Diffuse reflection\"."), HIDDEN_HEAT_MAP, null, null)
                : scene(HIDDEN_NAME, true, true, List.of(), null, null, null));
        int passed = hiddenFails ? 0 : 1;
        return new StudentResult(new Submission(folder, id, name, null, null, null), new StudentResult.Summary(false,
                passed, 2, new Category.Mistake(diagnosis), reason), scenes, Duration.ofMillis(millis),
                new Findings(null,
                        List.of(), List.of(), List.of(), List.of("handout section 3.2, \"Diffuse reflection\".")));
    }

    private static SceneResult scene(String name, boolean hidden, boolean passed, List<String> explanation,
            String heatMap, String yours, String expected) {
        return new SceneResult(name, hidden, passed, explanation, new SceneResult.Images(heatMap, yours, expected));
    }

    /** A 16 x 12 image: the left half {@code rgb}, the right half black. */
    private static BufferedImage image(int rgb) {
        BufferedImage image = new BufferedImage(16, 12, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 12; y++) {
            for (int x = 0; x < 8; x++) {
                image.setRGB(x, y, rgb);
            }
        }
        return image;
    }

    /** A student whose code did not compile, with no scene run: a result of the folder named. */
    static StudentResult notCompiled(String folder, String id, String name) {
        return new StudentResult(new Submission(folder, id, name, null, null, null), new StudentResult.Summary(false,
                0, 0, Category.Outcome.DOES_NOT_COMPILE, "The code does not compile."), List.of(),
                Duration.ofMillis(10));
    }

    /** The names of feedback.zip's entries in {@code report}, in order. */
    static List<String> zipEntries(Path report) throws IOException {
        List<String> names = new ArrayList<>();
        try (InputStream file = Files.newInputStream(report.resolve("feedback.zip"));
                ZipInputStream zip = new ZipInputStream(file, StandardCharsets.UTF_8)) {
            for (ZipEntry entry = zip.getNextEntry(); entry != null; entry = zip.getNextEntry()) {
                names.add(entry.getName());
            }
        }
        return names;
    }

    /** The grade the tests show: the pass mark of 1, as the gradebook writes it. */
    static String grade(StudentResult result) {
        return result.passed() ? "1.00" : "0.00";
    }
}
