package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.grading.SourceCheck.Sources;
import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

/**
 * The grade's compile step: the two files with the starter kit's others, compiled in a JVM that
 * runs none of the student's code (a cohort job's warm compiler, or a JVM of its own), into a
 * folder of the grader's that every later run is given read-only: so that nothing a run of the
 * code writes reaches the next run, the hidden scenes' above all. It compiles with {@code process}
 * in {@code sandbox}, within {@code timeLimit}.
 */
record CompileStep(Sandbox sandbox, StudentProcess process, Duration timeLimit) {

    /** How compiling went, where the classes are, and when it ended (the time limit's runs start then). */
    record Started(StudentProcess.Compiled compiled, Path classes, long renderStart) {
    }

    Started compile(Submission submission, Sources code, Path work) throws IOException, InterruptedException {
        Path sources = StudentProcess.writeSources(work, code.sphere(), code.renderer());
        sandbox.share(work);
        Path compiledFolder = childFolder(sandbox, work, "compiled");
        StudentProcess.Compiled compiled = process.compile(sources, compiledFolder, submission.sphere().path(),
                submission.renderer().path(), timeLimit);
        Path classes = compiledFolder.resolve(StudentHarness.CLASSES_FOLDER);
        if (compiled.compiled()) {
            sandbox.share(classes);
        }
        return new Started(compiled, classes, System.nanoTime());
    }

    /** An empty folder in {@code work} for the student's process to write in. */
    static Path childFolder(Sandbox sandbox, Path work, String name) throws IOException {
        Path folder = Files.createDirectory(work.resolve(name));
        sandbox.shareWritable(folder);
        return folder;
    }
}
