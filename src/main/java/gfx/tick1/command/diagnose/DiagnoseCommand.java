package gfx.tick1.command.diagnose;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.command.shared.diagnosis.Diagnoser;
import gfx.tick1.command.shared.diagnosis.Diagnosis;
import gfx.tick1.command.shared.diagnosis.SceneChange;
import gfx.tick1.engine.image.PngInput;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneException;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code tick1 diagnose}: which stage of the handout, or which common mistake, an image shows. */
@Command(name = "diagnose",
        description = {"Says which stage of the handout or common mistake an image shows.",
            "Renders the scene as each entry of a catalogue (the handout's stages, the correct image and the "
                    + "mistakes students make) and ranks them on the pixels where some entry draws a sphere, by the "
                    + "share that match exactly and within one level. An entry is named as the answer only when its "
                    + "render matches every pixel (a mistake also within 1 level on every pixel, as arithmetic in "
                    + "float or in another order gives); an image is correct only when every pixel is equal, and one "
                    + "within a level of the correct render is said to be so, with how many pixels differ. When no "
                    + "entry explains the image, a scene file one value away (a colour, the light's intensity or "
                    + "position, a sphere's centre or radius) whose correct render is the image is named; otherwise "
                    + "it says it is unsure and shows at most three candidates, near ties as ties.",
            "Without --scene the image is recognised as a render of tick1.xml or basic_scene.xml.",
            "Catalogue: background only; flat colour (Figure 4); ambient only (Figure 5a); ambient + diffuse; "
                    + "ambient term without C_diff; no ambient term; specular term without I; colour scaled by 255; "
                    + "colour divided by 255; correct (Figure 1); L and V not normalised (Figure 6a); N.L not "
                    + "clamped (Figure 6b); R.V not clamped (Figure 6c); far root; hit rejected when either root is "
                    + "negative; roots accepted at s >= 0; no distance fall-off; fall-off without 4 pi; V pointing "
                    + "away from the camera; R reflected the wrong way; rounding instead of truncating; image upside "
                    + "down; red and blue swapped."})
public final class DiagnoseCommand implements Callable<Integer> {

    @ExitStatus("the image is correct")
    public static final int EXIT_CORRECT = 0;
    @ExitStatus("not correct: an earlier stage or a mistake of the catalogue explains every pixel, every pixel is "
            + "within 1 level of the correct render, or the correct render of a scene with one value changed is the "
            + "image")
    public static final int EXIT_NOT_CORRECT = 1;
    @ExitStatus("the image or the scene cannot be read, the image is not of a scene it knows (give --scene), or the "
            + "command line is wrong")
    public static final int EXIT_CANNOT_DIAGNOSE = 2;
    @ExitStatus("no entry of the catalogue explains the image, or two come out level: candidates only")
    public static final int EXIT_UNSURE = 3;

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "IMAGE.png", description = "The image to diagnose.")
    private Path imageFile;

    @Option(names = "--scene", paramLabel = "SCENE.xml",
            description = "The scene the image shows (default: recognise tick1.xml or basic_scene.xml, built in).")
    private Path sceneFile;

    @Option(names = "--border", paramLabel = "PIXELS", defaultValue = "0",
            description = "Leave out a frame this many pixels wide (default: ${DEFAULT-VALUE}); the handout's "
                    + "Figure 6 images carry a 12-pixel red frame.")
    private int border;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        BufferedImage image;
        Map<String, Scene> scenes = new LinkedHashMap<>();
        try {
            image = PngInput.read(imageFile);
            if (sceneFile == null) {
                BundledScenes.STUDENT_SCENES.forEach(name -> scenes.put(name, BundledScenes.load(name)));
            } else {
                scenes.put(sceneFile.toString(), new SceneLoader(sceneFile, false).getScene());
            }
        } catch (IOException | SceneException e) {
            throw new CommandFailure(EXIT_CANNOT_DIAGNOSE, e.getMessage());
        }
        try {
            Diagnoser diagnoser = new Diagnoser(border, 1);
            // Given a scene, the image is diagnosed as that scene's even when it matches badly (the
            // report says so); without one, it must look like one of the scenes the kit renders.
            Optional<Diagnoser.SceneDiagnosis> found = sceneFile != null
                    ? Optional.of(new Diagnoser.SceneDiagnosis(sceneFile.toString(),
                            diagnoser.diagnose(image, scenes.get(sceneFile.toString()), sceneFile.toString())))
                    : diagnoser.recognise(image, scenes);
            if (found.isEmpty() || found.get().diagnosis().verdict() == Diagnosis.Verdict.UNSURE
                    || found.get().diagnosis().verdict() == Diagnosis.Verdict.LEVEL_OFF_CORRECT) {
                Integer slip = reportSceneSlip(diagnoser, image, scenes, found, out);
                if (slip != null) {
                    return slip;
                }
            }
            if (found.isEmpty()) {
                throw new CommandFailure(EXIT_CANNOT_DIAGNOSE, imageFile + ": not a render of "
                        + String.join(" or ", BundledScenes.STUDENT_SCENES) + "; give the scene with --scene");
            }
            Diagnoser.SceneDiagnosis result = found.get();
            Diagnosis diagnosis = result.diagnosis();
            out.println(header(image, result.scene()));
            // Where the spheres are the scene's, nothing here says the scene file differs: only a
            // scene with one value changed that renders to the image pixel for pixel says that
            // (reportSceneSlip), since a mistake no entry knows gives such an image as well.
            diagnosis.report().forEach(line -> out.println("  " + line));
            if (diagnosis.verdict() == Diagnosis.Verdict.UNSURE
                    && diagnoser.hasTheOutlineOf(image, scenes.get(result.scene()))) {
                out.println("  the spheres' outlines are exactly those of " + result.scene() + ", but no entry of the "
                        + "catalogue explains their colours.");
            }
            return switch (diagnosis.verdict()) {
                case CORRECT -> EXIT_CORRECT;
                case EXPLAINED, LEVEL_OFF_CORRECT -> EXIT_NOT_CORRECT;
                case UNSURE -> EXIT_UNSURE;
            };
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(EXIT_CANNOT_DIAGNOSE, "--border " + border + ": " + e.getMessage());
        }
    }

    private String header(BufferedImage image, String scene) {
        return imageFile + " (" + image.getWidth() + " x " + image.getHeight() + ") compared with " + scene
                + (border > 0 ? ", inside a " + border + "-pixel border" : "") + ":";
    }

    /**
     * When the correct render of a scene with one value changed is the image, pixel for pixel, says
     * so and returns the exit status; otherwise prints nothing and returns null. The scene is the
     * one recognised or given, or, when none was recognised, each the kit renders in turn; the
     * handout's example scene lends the values a student may have kept from it.
     */
    private Integer reportSceneSlip(Diagnoser diagnoser, BufferedImage image, Map<String, Scene> scenes,
            Optional<Diagnoser.SceneDiagnosis> found, PrintWriter out) {
        Scene example = BundledScenes.load(BundledScenes.BASIC);
        for (String name : found.map(f -> List.of(f.scene())).orElse(List.copyOf(scenes.keySet()))) {
            Scene scene = scenes.get(name);
            List<SceneChange> changes = diagnoser.sceneChangesExplaining(image, scene,
                    SceneChange.same(scene, example) ? null : example);
            if (!changes.isEmpty()) {
                boolean handout = SceneChange.same(scene, BundledScenes.load(BundledScenes.TICK1));
                String asked = askedBy(handout, name);
                out.println(header(image, name));
                out.println("  verdict: the scene differs: every pixel is the correct render of " + name
                        + " with one value changed: " + String.join("; or ", changes.stream()
                                .map(change -> change.describe(asked)).toList()) + ".");
                out.println("  likely cause: the scene file rendered is not " + name + "; the code drew that scene "
                        + "exactly as tick1 does.");
                out.println("  reread: " + (handout ? "handout section 3, \"Define a new scene\"" : name) + ".");
                return EXIT_NOT_CORRECT;
            }
        }
        return null;
    }

    /** "the handout's section 3 asks for" for the handout's tick1.xml, else "SCENE has". */
    private static String askedBy(boolean handout, String scene) {
        return handout ? "the handout's section 3 asks for" : scene + " has";
    }
}
