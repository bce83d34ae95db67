package gfx.tick1.command.starter;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.command.shared.kit.StarterKit.KitFile;
import gfx.tick1.command.shared.kit.StarterKit;
import gfx.tick1.engine.io.AtomicFile;
import gfx.tick1.engine.io.IoErrors;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code tick1 starter}: writes the student's starting kit, exactly what {@code grade} compiles against. */
@Command(name = "starter",
        description = {"Writes the starter kit as the handout's tick1/ folder, or its tick1.zip (--zip).",
            "The zip is the one to put on Moodle: it unpacks to tick1/, as the handout says.",
            "The kit holds src/gfx/tick1/ with the given classes (Camera, PointLight, "
                + "Ray, RaycastHit, Scene, SceneLoader, Tick1, Vector3), Sphere.java and Renderer.java with the "
                + "handout's TODOs, and basic_scene.xml."})
public final class StarterCommand implements Callable<Integer> {

    @ExitStatus("the kit was written")
    public static final int EXIT_OK = 0;
    @ExitStatus("the command line is wrong, or a file would be overwritten (see --force)")
    public static final int EXIT_WOULD_OVERWRITE = 2;
    @ExitStatus("the kit could not be written")
    public static final int EXIT_CANNOT_WRITE = 3;

    @Spec
    private CommandSpec spec;

    @Option(names = "--out", paramLabel = "DIR", defaultValue = StarterKit.KIT_FOLDER,
            description = "The folder to write the kit into, created if missing (default: ${DEFAULT-VALUE}, in "
                    + "the current folder, as the handout's tick1.zip unpacks).")
    private Path folder;

    @Option(names = "--zip", paramLabel = "FILE",
            description = "Write the kit as a zip instead of a folder, such as tick1.zip: it unpacks to "
                    + StarterKit.KIT_FOLDER + "/, as the handout says.")
    private Path zip;

    @Option(names = "--force", description = "Overwrite files of an earlier kit in the folder.")
    private boolean force;

    @Override
    public Integer call() {
        if (zip != null) {
            return writeZip();
        }
        List<KitFile> files = StarterKit.files();
        if (!force) {
            for (KitFile file : files) {
                Path target = folder.resolve(file.path());
                if (Files.exists(target)) {
                    throw new CommandFailure(EXIT_WOULD_OVERWRITE, target
                            + " already exists; use --force to overwrite the kit");
                }
            }
        }
        try {
            Files.createDirectories(folder);
        } catch (IOException e) {
            throw new CommandFailure(EXIT_CANNOT_WRITE, "cannot create the folder " + folder + ": "
                    + IoErrors.reason(e));
        }
        try {
            for (KitFile file : files) {
                file.writeUnder(folder);
            }
        } catch (IOException e) {
            throw new CommandFailure(EXIT_CANNOT_WRITE, "cannot write the kit: " + IoErrors.describe(e));
        }
        PrintWriter out = spec.commandLine().getOut();
        out.println("Wrote the starter kit to " + folder + ":");
        files.forEach(file -> out.println("  " + file.path()));
        sayWhatStudentsSubmit(out);
        return EXIT_OK;
    }

    private int writeZip() {
        if (spec.commandLine().getParseResult().hasMatchedOption("--out")) {
            throw new CommandFailure(EXIT_WOULD_OVERWRITE, "give --out or --zip, not both: the zip unpacks to "
                    + StarterKit.KIT_FOLDER + "/ wherever it is unpacked");
        }
        if (!force && Files.exists(zip)) {
            throw new CommandFailure(EXIT_WOULD_OVERWRITE, zip + " already exists; use --force to overwrite it");
        }
        try {
            Path parent = zip.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            AtomicFile.write(zip, StarterKit::writeZip);
        } catch (IOException e) {
            throw new CommandFailure(EXIT_CANNOT_WRITE, "cannot write the kit: " + IoErrors.describe(e));
        }
        PrintWriter out = spec.commandLine().getOut();
        out.println("Wrote the starter kit to " + zip + ", which unpacks to " + StarterKit.KIT_FOLDER + "/ with "
                + StarterKit.SOURCE_FOLDER + "*.java and " + StarterKit.BASIC_SCENE + ".");
        sayWhatStudentsSubmit(out);
        return EXIT_OK;
    }

    private static void sayWhatStudentsSubmit(PrintWriter out) {
        out.println("Students edit and submit " + StarterKit.SOURCE_FOLDER + "Sphere.java and "
                + StarterKit.SOURCE_FOLDER + "Renderer.java.");
    }
}
