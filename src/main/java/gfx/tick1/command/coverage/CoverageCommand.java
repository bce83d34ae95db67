package gfx.tick1.command.coverage;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.command.shared.coverage.CatalogueOnScenes;
import gfx.tick1.command.shared.coverage.Coverage;
import gfx.tick1.command.shared.coverage.GradingScenes;
import gfx.tick1.command.shared.coverage.NamedScene;
import gfx.tick1.command.shared.coverage.SceneSearch;
import gfx.tick1.engine.io.AtomicFile;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.scene.SceneException;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code tick1 coverage}: which catalogued mistakes the grading scenes catch, and which none of them can. */
@Command(name = "coverage",
        description = {"Says which catalogued mistakes the grading scenes catch.",
            "For tick1.xml and the built-in hidden scene (or the scenes of --scenes), it renders each scene as every "
                    + "mistake of the diagnose catalogue at the grading size and counts the pixels that differ from "
                    + "the image a pass needs: a scene catches a mistake when one pixel differs. It lists what each "
                    + "scene alone catches, what no scene catches (with the reason where tick1 knows one), and the "
                    + "pairs of mistakes grade names together that some scene catches neither of alone.",
            "With --suggest it writes a hidden scene that catches every mistake any scene of the tick can show."})
public final class CoverageCommand implements Callable<Integer> {

    @ExitStatus("the coverage was reported, and every file asked for written")
    public static final int EXIT_OK = 0;
    @ExitStatus("the command line is wrong, or a scene cannot be read or graded with")
    public static final int EXIT_USAGE = 2;
    @ExitStatus("a file asked for could not be written")
    public static final int EXIT_CANNOT_WRITE = 3;

    @Spec
    private CommandSpec spec;

    @Option(names = "--scenes", paramLabel = "DIR",
            description = "Judge tick1.xml and every *.xml in DIR, as tick1 grade --scenes DIR grades, instead of "
                    + "tick1.xml and the built-in hidden scene.")
    private Path scenesFolder;

    @Option(names = "--csv", paramLabel = "FILE",
            description = "Also write the pixel counts as CSV: Mistake,Scene,Pixels differing, one row per mistake "
                    + "and scene, then the pairs.")
    private Path csv;

    @Option(names = "--html", paramLabel = "FILE", description = "Also write the report as an HTML page.")
    private Path html;

    @Option(names = "--suggest", paramLabel = "FILE",
            description = "Also write a scene to grade on as a hidden scene, found by a search that starts from "
                    + "tick1.xml's layout, that catches every mistake any scene of the tick can show.")
    private Path suggest;

    @Option(names = "--width", paramLabel = "PIXELS", defaultValue = "640",
            description = "Image width (default: ${DEFAULT-VALUE}, as tick1 grade grades).")
    private int width;

    @Option(names = "--height", paramLabel = "PIXELS", defaultValue = "480",
            description = "Image height (default: ${DEFAULT-VALUE}).")
    private int height;

    @Override
    public Integer call() {
        if (width < 1 || width > 4096 || height < 1 || height > 4096) {
            throw new ParameterException(spec.commandLine(), "--width and --height must be from 1 to 4096, not "
                    + width + " x " + height);
        }
        List<NamedScene> scenes;
        try {
            scenes = scenesFolder == null ? GradingScenes.builtIn() : GradingScenes.withFolder(scenesFolder);
        } catch (SceneException e) {
            throw new CommandFailure(EXIT_USAGE, e.getMessage());
        } catch (IOException e) {
            throw new CommandFailure(EXIT_USAGE, IoErrors.describe(e));
        }
        Coverage coverage = CatalogueOnScenes.measure(scenes, width, height);
        PrintWriter out = spec.commandLine().getOut();
        CoverageTable.lines(coverage).forEach(out::println);
        out.flush();
        write(csv, CoverageCsv.of(coverage));
        write(html, CoveragePage.of(coverage));
        if (suggest != null) {
            SceneSearch.Suggestion suggestion = SceneSearch.find(width, height);
            if (suggestion == null) {
                throw new CommandFailure(EXIT_USAGE, "--suggest: no scene of the search is fair at " + width + " x "
                        + height + " (the handout's six steps fail it, or its two references differ)");
            }
            write(suggest, suggestion.xml());
            out.println();
            SuggestionReport.lines(suggestion, suggest).forEach(out::println);
        }
        return EXIT_OK;
    }

    private static void write(Path file, String text) {
        if (file == null) {
            return;
        }
        try {
            AtomicFile.write(file, out -> out.write(text.getBytes(StandardCharsets.UTF_8)));
        } catch (IOException e) {
            throw new CommandFailure(EXIT_CANNOT_WRITE, "cannot write " + file + ": " + IoErrors.describe(e));
        }
    }
}
