package gfx.tick1.command.compare;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.ImageFormat;
import gfx.tick1.engine.image.PngInput;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.io.Counted;
import gfx.tick1.engine.io.IoErrors;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code tick1 compare}: how far one image is from another, in figures and as a heat map. */
@Command(name = "compare",
        description = {"Compares two PNG images pixel by pixel.",
            "It prints how many pixels differ, the largest and mean difference per channel (in levels of 0 to "
                    + "255), PSNR and the bounding box of the differences."})
public final class CompareCommand implements Callable<Integer> {

    @ExitStatus("every pixel is within the tolerance")
    public static final int EXIT_SAME = 0;
    @ExitStatus("some pixel differs by more than the tolerance")
    public static final int EXIT_DIFFERENT = 1;
    @ExitStatus("the images cannot be compared (bad command line, unreadable image, sizes differ)")
    public static final int EXIT_CANNOT_COMPARE = 2;
    @ExitStatus("the heat map could not be written")
    public static final int EXIT_CANNOT_WRITE = 3;

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "EXPECTED.png", description = "The image that is right.")
    private Path expectedFile;

    @Parameters(index = "1", paramLabel = "ACTUAL.png", description = "The image to check.")
    private Path actualFile;

    @Option(names = "--diff", paramLabel = "HEATMAP.png",
            description = "Also write a heat map of the differences over a dimmed copy of the expected image, "
                    + "with its key below: where ACTUAL is brighter, dark red for 1 level, through orange, to "
                    + "yellow-white for 64 levels or more; where it is darker, dark blue through blue to pale cyan.")
    private Path heatMapFile;

    @Option(names = "--unsigned",
            description = "With --diff: draw how far each pixel is off only, not which way, all in the "
                    + "brighter colours (dark red to yellow-white).")
    private boolean unsigned;

    @Option(names = "--tolerance", paramLabel = "LEVELS", defaultValue = "0",
            description = "The largest difference per channel that still counts as the same (default: "
                    + "${DEFAULT-VALUE}, pixel for pixel).")
    private int tolerance;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        if (tolerance < 0 || tolerance > 255) {
            // Reported and answered with exit status 2 like any other usage error (the start-up's handler).
            throw new ParameterException(spec.commandLine(), "--tolerance " + tolerance + ": must be from 0 to 255");
        }
        if (heatMapFile != null && ImageFormat.ofName(heatMapFile.toString()).filter(f -> f != ImageFormat.PNG)
                .isPresent()) {
            throw new ParameterException(spec.commandLine(), "--diff " + heatMapFile + ": the heat map is a PNG; "
                    + "name it " + ImageFormat.asPng(heatMapFile.toString()));
        }
        ImageDifference difference;
        try {
            BufferedImage expected = PngInput.read(expectedFile);
            BufferedImage actual = PngInput.read(actualFile);
            difference = ImageDifference.between(expected, actual);
        } catch (IOException | IllegalArgumentException e) {
            throw new CommandFailure(EXIT_CANNOT_COMPARE, e.getMessage());
        }
        print(difference, out);
        if (heatMapFile != null) {
            try {
                PngOutput.write(unsigned ? difference.heatMapWithLegend() : difference.signedHeatMapWithLegend(),
                        heatMapFile);
            } catch (IOException e) {
                throw new CommandFailure(EXIT_CANNOT_WRITE, heatMapFile + ": cannot write the heat map: "
                        + IoErrors.reason(e));
            }
            out.println("heat map: " + heatMapFile);
        }
        boolean same = difference.isWithin(tolerance);
        out.println(same ? verdictSame(difference) : verdictDifferent(difference));
        return same ? EXIT_SAME : EXIT_DIFFERENT;
    }

    private String verdictSame(ImageDifference difference) {
        return difference.differingPixels() == 0 ? "SAME: identical pixel for pixel"
                : "SAME within the tolerance of " + Counted.of(tolerance, "level");
    }

    private String verdictDifferent(ImageDifference difference) {
        int beyond = difference.pixelsDifferingByMoreThan(tolerance);
        return "DIFFERENT: " + Counted.of(beyond, "pixel") + (beyond == 1 ? " differs" : " differ")
                + (tolerance == 0 ? "" : " by more than " + Counted.of(tolerance, "level"));
    }

    /** The figures, one per line, in the order a person reads them. */
    static void print(ImageDifference d, PrintWriter out) {
        int[] max = d.maxPerChannel();
        double[] mean = d.meanPerChannel();
        out.printf("pixels differing: %d of %d (%.3f%%); within 1 level: %.3f%%%n", d.differingPixels(),
                d.totalPixels(), 100.0 * d.differingPixels() / d.totalPixels(), 100 * d.shareWithin(1));
        out.printf("max difference:   R %d, G %d, B %d levels%n", max[0], max[1], max[2]);
        out.printf("mean difference:  R %.4f, G %.4f, B %.4f levels%n", mean[0], mean[1], mean[2]);
        out.printf("PSNR:             %s%n", Double.isInfinite(d.psnr()) ? "infinite (identical)"
                : String.format("%.2f dB", d.psnr()));
        out.printf("bounding box:     %s%n", d.boundingBox());
    }
}
