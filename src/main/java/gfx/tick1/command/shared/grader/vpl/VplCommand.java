package gfx.tick1.command.shared.grader.vpl;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.command.shared.coverage.ScenesShortfall;
import gfx.tick1.engine.io.IoErrors;
import java.io.IOException;
import java.io.PrintWriter;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code tick1 vpl}: the execution files of a Tick 1 activity in Moodle's Virtual Programming Lab, whose
 * Evaluate runs {@code tick1 grade --format vpl} (see {@link VplReport}), and a README.txt for staff.
 */
@Command(name = "vpl",
        description = {"Writes the files that make tick1 the tester of a Tick 1 activity on Moodle VPL.",
            "They are vpl_evaluate.sh and the hidden scenes of --scenes, the activity's execution files, and "
                + "README.txt, which says how to set up the activity and the jail's host (Moodle's Virtual "
                + "Programming Lab).",
            "When a student presses Evaluate, vpl_evaluate.sh grades their Sphere.java and Renderer.java with "
                + "tick1 grade --format vpl, in tick1's sandbox, and VPL shows tick1's verdict, reasons and notes with "
                + "the proposed grade. Where the sandbox cannot be made, nothing is graded and staff are told why."})
public final class VplCommand implements Callable<Integer> {

    @ExitStatus("the files were written")
    public static final int EXIT_OK = 0;
    @ExitStatus("the command line is wrong, a scene of --scenes cannot be graded with, other users cannot run the "
            + "tick1 that vpl_evaluate.sh would run, or a file would be overwritten (see --force)")
    public static final int EXIT_USAGE = 2;
    @ExitStatus("the files could not be written")
    public static final int EXIT_CANNOT_WRITE = 3;

    /** The execution file VPL runs for Evaluate. */
    public static final String EVALUATE = VplFiles.EVALUATE;
    /** How a hidden scene's execution file is named: this, then its number and .xml. */
    public static final String HIDDEN_PREFIX = "tick1-hidden-";
    static final String README = VplFiles.README;

    @Spec
    private CommandSpec spec;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "tick1-vpl",
            description = "The folder to write the files into, created if missing (default: ${DEFAULT-VALUE}).")
    private Path folder;

    @Option(names = "--scenes", paramLabel = "DIR",
            description = "Grade on tick1.xml and every *.xml of DIR, as tick1 grade --scenes does, instead of the "
                    + "built-in hidden scene, which is public. They are copied into --out as " + HIDDEN_PREFIX
                    + "1.xml, " + HIDDEN_PREFIX + "2.xml, ... (names that tell nothing of them), execution files of "
                    + "the activity.")
    private Path scenes;

    @Option(names = "--max-grade", paramLabel = "G",
            description = "The grade of a pass, within the activity's grades (default: the activity's maximum grade, "
                    + "VPL_GRADEMAX). A fail is the activity's minimum grade.")
    private String maxGrade;

    @Option(names = "--tick1", paramLabel = "PATH",
            description = "The tick1 that vpl_evaluate.sh runs, as the jail sees it (default: this tick1's launcher, "
                    + "by its absolute path).")
    private Path tick1;

    @Option(names = "--force", description = "Overwrite the files of an earlier tick1 vpl in the folder.")
    private boolean force;

    @Override
    public Integer call() {
        if (maxGrade != null) {
            try {
                GradeRange.parse("0:" + maxGrade);
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), "--max-grade " + maxGrade + ": " + e.getMessage());
            }
        }
        Path launcher = launcher();
        String unreachable = RunnableByOthers.problem(launcher);
        if (unreachable != null) {
            throw new CommandFailure(EXIT_USAGE, unreachable);
        }
        List<Path> hidden = hiddenScenes();
        List<String> sceneFiles = new ArrayList<>();
        for (int i = 1; i <= hidden.size(); i++) {
            sceneFiles.add(HIDDEN_PREFIX + i + ".xml");
        }
        VplFiles files = new VplFiles(launcher, maxGrade, sceneFiles,
                VplCommand.class.getPackage().getImplementationVersion());
        List<String> names = new ArrayList<>(List.of(EVALUATE, README));
        names.addAll(files.sceneFiles());
        checkNotThere(names);
        try {
            Files.createDirectories(folder);
            Path evaluate = folder.resolve(EVALUATE);
            Files.writeString(evaluate, files.evaluateScript());
            Files.setPosixFilePermissions(evaluate, PosixFilePermissions.fromString("rwxr-xr-x"));
            Files.writeString(folder.resolve(README), files.readme());
            for (int i = 0; i < hidden.size(); i++) {
                Files.copy(hidden.get(i), folder.resolve(files.sceneFiles().get(i)),
                        java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (IOException | UnsupportedOperationException e) {
            throw new CommandFailure(EXIT_CANNOT_WRITE, "cannot write the files into " + folder + ": "
                    + (e instanceof IOException io ? IoErrors.describe(io) : e.getMessage()));
        }
        PrintWriter out = spec.commandLine().getOut();
        out.println("Wrote the execution files of a Tick 1 VPL activity to " + folder + ":");
        names.forEach(name -> out.println("  " + name));
        out.println("vpl_evaluate.sh runs " + launcher + ". " + README + " says how to set up the activity.");
        ScenesShortfall.of(scenes, 640, 480).ifPresent(shortfall -> spec.commandLine().getErr().println(
                "tick1 vpl: warning: " + shortfall.line(scenes)));
        return EXIT_OK;
    }

    /** The tick1 the script runs: --tick1, else the launcher of this tick1's installation. */
    private Path launcher() {
        if (tick1 != null) {
            if (!tick1.isAbsolute()) {
                throw new ParameterException(spec.commandLine(), "--tick1 " + tick1 + ": give an absolute path, as "
                        + "the jail sees it");
            }
            return tick1;
        }
        try {
            Path jar = Path.of(VplCommand.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            Path bin = jar.toAbsolutePath().getParent().resolveSibling("bin").resolve("tick1");
            if (jar.toString().endsWith(".jar") && Files.isExecutable(bin)) {
                return bin.normalize();
            }
        } catch (URISyntaxException | SecurityException | IllegalArgumentException e) {
            // Not installed from a jar: --tick1 must say where.
        }
        throw new CommandFailure(EXIT_USAGE, "cannot tell where this tick1's launcher is (it does not run from an "
                + "installed tick1): give --tick1 PATH");
    }

    /** The *.xml of --scenes, each checked as tick1 grade checks its scenes, in name order; empty without it. */
    private List<Path> hiddenScenes() {
        if (scenes == null) {
            return List.of();
        }
        List<Path> xml;
        try (Stream<Path> files = Files.list(scenes)) {
            xml = files.filter(f -> f.getFileName().toString().endsWith(".xml") && Files.isRegularFile(f)).sorted()
                    .toList();
        } catch (IOException e) {
            throw new CommandFailure(EXIT_USAGE, "--scenes " + scenes + ": " + IoErrors.describe(e));
        }
        if (xml.isEmpty()) {
            throw new CommandFailure(EXIT_USAGE, scenes + ": no *.xml scene files in the folder");
        }
        String problem = VplFiles.checkScenes(scenes);
        if (problem != null) {
            throw new CommandFailure(EXIT_USAGE, problem);
        }
        return xml;
    }

    private void checkNotThere(List<String> names) {
        if (force) {
            return;
        }
        for (String name : names) {
            if (Files.exists(folder.resolve(name))) {
                throw new CommandFailure(EXIT_USAGE, folder.resolve(name) + " already exists; use --force to "
                        + "overwrite it");
            }
        }
    }
}
