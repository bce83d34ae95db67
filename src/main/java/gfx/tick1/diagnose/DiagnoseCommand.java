package gfx.tick1.diagnose;

import gfx.tick1.image.PngInput;
import gfx.tick1.scene.BundledScenes;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.SceneException;
import gfx.tick1.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code tick1 diagnose}: which stage of the handout, or which common mistake, an image shows. */
@Command(name = "diagnose", mixinStandardHelpOptions = true, sortOptions = false, usageHelpAutoWidth = true,
        description = {
            "Renders the scene as each entry of a catalogue (the handout's stages, the correct image and the "
                    + "mistakes students make) and says which one the image is closest to, with the share of pixels "
                    + "that match exactly and within one level, the top three, why, and what to reread.",
            "Catalogue: background only; flat colour (Figure 4); ambient only (Figure 5a); ambient + diffuse; "
                    + "correct (Figure 1); L and V not normalised (Figure 6a); N.L not clamped (Figure 6b); R.V not "
                    + "clamped (Figure 6c); far root; no distance fall-off; fall-off without 4 pi; V pointing away "
                    + "from the camera; R reflected the wrong way; rounding instead of truncating; image upside "
                    + "down; red and blue swapped."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:the image is closest to the correct image",
            "1:the image is closest to an earlier stage or a mistake",
            "2:the image or the scene cannot be read, or the command line is wrong",
            "4:an internal error (a bug: please report it)"})
public final class DiagnoseCommand implements Callable<Integer> {

    public static final int EXIT_CORRECT = 0;
    public static final int EXIT_NOT_CORRECT = 1;
    public static final int EXIT_CANNOT_DIAGNOSE = 2;

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "IMAGE.png", description = "The image to diagnose.")
    private Path imageFile;

    @Option(names = "--scene", paramLabel = "SCENE.xml",
            description = "The scene the image shows (default: the handout's tick1.xml, built in).")
    private Path sceneFile;

    @Option(names = "--border", paramLabel = "PIXELS", defaultValue = "0",
            description = "Leave out a frame this many pixels wide (default: ${DEFAULT-VALUE}); the handout's "
                    + "Figure 6 images carry a 12-pixel red frame.")
    private int border;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        BufferedImage image;
        Scene scene;
        try {
            image = PngInput.read(imageFile);
            scene = sceneFile == null ? BundledScenes.load(BundledScenes.TICK1)
                    : new SceneLoader(sceneFile, false).getScene();
        } catch (IOException | SceneException e) {
            err.println("tick1 diagnose: " + e.getMessage());
            return EXIT_CANNOT_DIAGNOSE;
        }
        Diagnosis diagnosis;
        try {
            diagnosis = new Diagnoser(border).diagnose(image, scene);
        } catch (IllegalArgumentException e) {
            err.println("tick1 diagnose: --border " + border + ": " + e.getMessage());
            return EXIT_CANNOT_DIAGNOSE;
        }
        out.println(imageFile + " (" + image.getWidth() + " x " + image.getHeight() + ") as a render of "
                + (sceneFile == null ? "the handout's tick1.xml" : sceneFile)
                + (border > 0 ? ", inside a " + border + "-pixel border" : "") + ":");
        diagnosis.report().forEach(line -> out.println("  " + line));
        return diagnosis.closest().variant().isCorrect() ? EXIT_CORRECT : EXIT_NOT_CORRECT;
    }
}
