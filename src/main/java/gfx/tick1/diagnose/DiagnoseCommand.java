package gfx.tick1.diagnose;

import gfx.tick1.cli.CommandFailure;
import gfx.tick1.cli.ExitStatus;
import gfx.tick1.image.PngInput;
import gfx.tick1.scene.BundledScenes;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.SceneException;
import gfx.tick1.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.LinkedHashMap;
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
        description = {
            "Renders the scene as each entry of a catalogue (the handout's stages, the correct image and the "
                    + "mistakes students make) and ranks them on the pixels where some entry draws a sphere, by the "
                    + "share that match exactly and within one level. An entry is named as the answer only when its "
                    + "render matches every pixel (the correct image also within 1 level on every pixel, as "
                    + "arithmetic in another order gives); otherwise it says it is unsure and shows at most three "
                    + "candidates, near ties as ties.",
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
    @ExitStatus("an earlier stage or a mistake of the catalogue explains every pixel")
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
        Diagnoser.SceneDiagnosis result;
        try {
            Diagnoser diagnoser = new Diagnoser(border, 1);
            // Given a scene, the image is diagnosed as that scene's even when it matches badly (the
            // report says so); without one, it must look like one of the scenes the kit renders.
            Optional<Diagnoser.SceneDiagnosis> found = sceneFile != null
                    ? Optional.of(new Diagnoser.SceneDiagnosis(sceneFile.toString(),
                            diagnoser.diagnose(image, scenes.get(sceneFile.toString()))))
                    : diagnoser.recognise(image, scenes);
            if (found.isEmpty()) {
                throw new CommandFailure(EXIT_CANNOT_DIAGNOSE, imageFile + ": not a render of "
                        + String.join(" or ", BundledScenes.STUDENT_SCENES) + "; give the scene with --scene");
            }
            result = found.get();
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(EXIT_CANNOT_DIAGNOSE, "--border " + border + ": " + e.getMessage());
        }
        out.println(imageFile + " (" + image.getWidth() + " x " + image.getHeight() + ") as a render of "
                + result.scene() + (border > 0 ? ", inside a " + border + "-pixel border" : "") + ":");
        result.diagnosis().report().forEach(line -> out.println("  " + line));
        return switch (result.diagnosis().verdict()) {
            case CORRECT -> EXIT_CORRECT;
            case EXPLAINED -> EXIT_NOT_CORRECT;
            case UNSURE -> EXIT_UNSURE;
        };
    }
}
