package gfx.tick1.command.shared.grader.sandbox;

import gfx.tick1.command.shared.grader.harness.StudentCompiler;
import gfx.tick1.command.shared.grader.harness.StudentHarness;
import gfx.tick1.command.shared.grader.sandbox.SandboxedProcess.Run;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Batch;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Compiled;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Result;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * What a run of the harness left in its output folder, and how it ended, read as the grade needs
 * it: what compiling gave, and each scene's outcome. Every file is the student's code's to have
 * changed, so each is read capped, as a regular file only ({@link ChildOutput}).
 */
final class HarnessOutput {

    private HarnessOutput() {
    }

    /** What a run that compiled (or tried to) with a heap of {@code heapMegabytes} says about compiling. */
    static Compiled compiled(Run run, Path output, Duration timeLimit, int heapMegabytes) throws IOException {
        if (run.limitReached() != null) {
            return new Compiled(List.of(), run.limitReached().words());
        }
        if (!run.finished()) {
            return new Compiled(List.of(),
                    "the compiler did not finish within the time limit of " + describe(timeLimit));
        }
        String outOfMemory = StudentCompiler.OUT_OF_MEMORY + " (its heap limit is " + heapMegabytes + " MiB)";
        if (run.exitStatus() == StudentHarness.DOES_NOT_COMPILE) {
            byte[] errors = ChildOutput.read(output.resolve(StudentHarness.ERRORS_FILE), ChildOutput.TEXT_CAP);
            if (errors != null && errors.length > 0) {
                List<String> list = Arrays.stream(new String(errors, StandardCharsets.UTF_8).split("\0"))
                        .map(ChildOutput::printable).toList();
                return list.equals(List.of(StudentCompiler.OUT_OF_MEMORY)) ? new Compiled(List.of(), outOfMemory)
                        : new Compiled(list, null);
            }
        }
        if (run.outputTail().contains("OutOfMemoryError")) {
            return new Compiled(List.of(), outOfMemory);
        }
        if (run.exitStatus() != 0 || !ChildOutput.isDirectory(output.resolve(StudentHarness.CLASSES_FOLDER))) {
            String said = run.outputTail().strip();
            return new Compiled(List.of(), "the compiler stopped with exit status " + run.exitStatus()
                    + (said.isEmpty() ? "" : ": " + said.lines().reduce((first, last) -> last).orElse("")));
        }
        return new Compiled(List.of(), null);
    }

    /** Each scene's outcome of a run that rendered {@code batch} within {@code timeLimit}, with what it wrote. */
    static Result rendered(Run run, Path output, Batch batch, Duration timeLimit) throws IOException {
        String progressText = ChildOutput.readText(output.resolve(StudentHarness.PROGRESS_FILE));
        List<Outcome> outcomes = new ArrayList<>();
        List<String> traces = new ArrayList<>();
        for (int i = 0; i < batch.sceneFiles().size(); i++) {
            outcomes.add(progressText == null && run.finished() && run.exitStatus() == 0
                    ? new Outcome.Failed(NoImage.ENDED, "no image: the log of the run's progress is missing, "
                            + "unreadable or not a regular file (did the code remove, replace or chmod it?)")
                    : outcome(output, i, progressText == null ? List.of() : progressText.lines().toList(), run,
                            batch, timeLimit));
            traces.add(ChildOutput.readText(output.resolve(i + StudentHarness.TRACE_SUFFIX)));
        }
        return new Result(run.limitReached() == null ? outcomes
                : outcomes.stream().map(outcome -> withLimit(outcome, run.limitReached())).toList(), run.outputTail(),
                traces, ChildOutput.readText(output.resolve(StudentHarness.PROBES_FILE), ChildOutput.PROBES_CAP));
    }

    /**
     * A scene's outcome when the run reached a total. Memory and the output folder's cap fail every
     * scene with the total's words (a process was killed, or the run stopped, so nothing of the run
     * counts); the process total follows the scene's own failure, on a line of its own (which a
     * hidden scene's report leaves out with the rest of the code's words), as the run went on.
     */
    private static Outcome withLimit(Outcome outcome, LimitReached limit) {
        if (limit.stoppedTheRun()) {
            return new Outcome.Failed(limit.kind(), limit.words());
        }
        return outcome instanceof Outcome.Failed failed
                ? new Outcome.Failed(failed.why(), failed.reason() + "\n" + limit.words(), true) : outcome;
    }

    private static Outcome outcome(Path output, int index, List<String> progress, Run run, Batch batch,
            Duration timeLimit) throws IOException {
        Path image = output.resolve(index + ".png");
        String error = ChildOutput.readText(output.resolve(index + ".error"));
        if (error != null) {
            return new Outcome.Failed(NoImage.THREW, "the code threw " + error);
        }
        if (progress.contains("end " + index) && ChildOutput.isRegularFile(image)) {
            try {
                return new Outcome.Rendered(ChildOutput.readPng(image, batch.width(), batch.height()));
            } catch (ChildOutput.Unusable e) {
                return new Outcome.Failed(NoImage.ENDED,
                        "the image written for this scene is unusable: " + e.getMessage());
            }
        }
        if (!run.finished()) {
            if (!progress.contains("start " + index) && index > 0) {
                return new Outcome.Failed(NoImage.TIME_LIMIT,
                        "not rendered: the time limit was reached at an earlier scene");
            }
            return new Outcome.Failed(NoImage.TIME_LIMIT, "no image within the time limit of " + describe(timeLimit)
                    + " (an infinite loop?); the program was stopped");
        }
        if (!progress.contains("start " + index)) {
            return new Outcome.Failed(NoImage.ENDED, "not rendered: the run stopped at an earlier scene");
        }
        int exitStatus = run.exitStatus();
        return new Outcome.Failed(NoImage.ENDED, "the program ended while rendering this scene, with exit status "
                + exitStatus
                + (exitStatus == 0 ? " (does the code call System.exit?)" : " (System.exit, or the JVM crashed)"));
    }

    private static String describe(Duration duration) {
        long millis = duration.toMillis();
        return millis % 1000 == 0 ? millis / 1000 + " s" : millis / 1000.0 + " s";
    }
}
