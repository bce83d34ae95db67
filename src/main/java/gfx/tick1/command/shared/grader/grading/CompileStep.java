package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.grading.SourceCheck.Sources;
import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.kit.StarterKit;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

/**
 * The grade's compile step: the two files with the starter kit's others, compiled in a JVM that
 * runs none of the student's code (a cohort job's warm compiler, or a JVM of its own), into a
 * folder of the grader's that every later run is given read-only: so that nothing a run of the
 * code writes reaches the next run, the hidden scenes' above all.
 */
final class CompileStep {

    /** How compiling went, where the classes are, and when it ended (the time limit's runs start then). */
    record Started(StudentProcess.Compiled compiled, Path classes, long renderStart) {
    }

    private final Sandbox sandbox;
    private final StudentProcess process;
    private final Duration timeLimit;

    CompileStep(Sandbox sandbox, StudentProcess process, Duration timeLimit) {
        this.sandbox = sandbox;
        this.process = process;
        this.timeLimit = timeLimit;
    }

    Started compile(Submission submission, Sources code, Path work) throws IOException, InterruptedException {
        Path sources = writeSources(work, code);
        Path compiledFolder = childFolder(sandbox, work, "compiled");
        StudentProcess.Compiled compiled = process.compile(sources, compiledFolder, submission.sphere().path(),
                submission.renderer().path(), timeLimit);
        Path classes = compiledFolder.resolve(StudentHarness.CLASSES_FOLDER);
        if (compiled.compiled()) {
            sandbox.share(classes, false);
        }
        return new Started(compiled, classes, System.nanoTime());
    }

    /** The two files and the starter kit's others in {@code work}/sources, shared with the sandbox. */
    private Path writeSources(Path work, Sources code) throws IOException {
        Path sources = Files.createDirectory(work.resolve("sources"));
        Files.writeString(sources.resolve("Sphere.java"), code.sphere(), StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("Renderer.java"), code.renderer(), StandardCharsets.UTF_8);
        for (String given : StarterKit.GIVEN_CLASSES) {
            Files.writeString(sources.resolve(given + ".java"), StarterKit.source(given), StandardCharsets.UTF_8);
        }
        sandbox.share(work, false);
        return sources;
    }

    /** An empty folder in {@code work} for the student's process to write in. */
    static Path childFolder(Sandbox sandbox, Path work, String name) throws IOException {
        Path folder = Files.createDirectory(work.resolve(name));
        sandbox.share(folder, true);
        return folder;
    }
}
