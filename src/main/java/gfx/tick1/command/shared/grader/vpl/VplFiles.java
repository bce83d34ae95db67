package gfx.tick1.command.shared.grader.vpl;

import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.grading.ReferenceChoice;
import gfx.tick1.command.shared.grader.sandbox.Leftovers;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.scene.SceneException;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

/**
 * The text of a Tick 1 activity's vpl_evaluate.sh and README.txt: tick1's templates with this activity's
 * launcher, pass grade and hidden scenes filled in.
 *
 * @param launcher   the tick1 the script runs, as the jail sees it
 * @param maxGrade   the grade of a pass, or null for the activity's maximum
 * @param sceneFiles the hidden scenes' execution file names, in order (empty: the built-in hidden scene)
 * @param version    tick1's version, or null for a development build
 */
public record VplFiles(Path launcher, String maxGrade, List<String> sceneFiles, String version) {

    /** The script VPL's Evaluate runs. */
    public static final String EVALUATE = "vpl_evaluate.sh";
    /** How to set up the activity, for staff. */
    public static final String README = "README.txt";

    /** vpl_evaluate.sh. */
    public String evaluateScript() {
        return template("vpl_evaluate.sh.txt")
                .replace("@TICK1@", shellQuoted(launcher.toString()))
                .replace("@MAX_GRADE@", maxGrade == null ? "''" : shellQuoted(maxGrade))
                .replace("@HIDDEN_SCENES@", Integer.toString(sceneFiles.size()))
                .replace("@NOT_SET_UP@", VplReport.notSetUp())
                .replace("@VERSION@", versionShown());
    }

    /** README.txt, for staff. */
    public String readme() {
        String pass = maxGrade == null ? "the activity's maximum grade" : maxGrade;
        return template(README)
                .replace("@TICK1@", launcher.toString())
                .replace("@VERSION@", versionShown())
                .replace("@GRADES@", "a pass is " + pass + ", a fail the activity's minimum grade")
                .replace("@PASS@", pass)
                .replace("@SCENE_FILES@", sceneFiles.isEmpty() ? "" : " and the " + sceneFiles.size() + " hidden "
                        + "scenes (" + String.join(", ", sceneFiles) + ")")
                .replace("@RUN_DEBUG@", sceneFiles.isEmpty() ? "" : ", hidden scenes and all, and there the "
                        + "student's own code runs, outside tick1's sandbox")
                + (sceneFiles.isEmpty() ? BUILT_IN_SCENE : "");
    }

    private static final String BUILT_IN_SCENE = """

            The hidden scene
            ----------------
            These files grade on tick1.xml and tick1's built-in hidden scene, which is public (it is in
            tick1, which students have): anyone can pass it by copying its images. For a grade that
            counts, write the files again with "tick1 vpl --scenes DIR", DIR holding scenes of your own.
            """;

    private String versionShown() {
        return version == null ? "development build" : version;
    }

    /**
     * Why the scenes of {@code folder} cannot be graded with, as tick1 grade --scenes would say, or null.
     */
    public static String checkScenes(Path folder) {
        Path work = null;
        try {
            work = Leftovers.newWorkFolder("vpl");
            Grading.prepare(work, folder, new Grading.Limits(1, 1, Duration.ofSeconds(1), 64, ReferenceChoice.either));
            return null;
        } catch (SceneException e) {
            return e.getMessage();
        } catch (IOException e) {
            return IoErrors.describe(e);
        } finally {
            if (work != null) {
                WorkFolder.delete(work);
            }
        }
    }

    /** {@code text} in single quotes for the shell. */
    static String shellQuoted(String text) {
        return "'" + text.replace("'", "'\"'\"'") + "'";
    }

    private static String template(String name) {
        try (InputStream in = VplFiles.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("tick1 is missing its resource " + name);
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
