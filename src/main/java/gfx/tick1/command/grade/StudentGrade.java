package gfx.tick1.command.grade;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.OutputGate;
import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.grading.SubmissionGrader;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Leftovers;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.command.shared.grader.vpl.GradeRange;
import gfx.tick1.command.shared.grader.vpl.VplReport;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.scene.SceneException;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * {@code tick1 grade --sphere --renderer}: one student's grade, in a work folder of its own, in tick1's format or
 * in VPL's, and its stop (Ctrl-C, SIGTERM): the student's process stopped, the work folder deleted, and one line
 * that says there is no verdict, after which the grade's outputs are shut. {@link GradeCommand} parses the command
 * line and hands it the options as values, the sandbox made and the stop, with the outputs' gate.
 */
final class StudentGrade {

    /** What a grade stopped by Ctrl-C or SIGTERM says. */
    private static final String STOPPED = "the grade was stopped (Ctrl-C or SIGTERM); no verdict";
    /** The line that says so. */
    static final String STOPPED_LINE = "tick1 grade: " + STOPPED;

    private final GradeOptions options;
    private final Path sphere;
    private final Path renderer;
    /** With --format vpl, the grades of a fail and of a pass; null for tick1's own format. */
    private final GradeRange vplRange;
    private final Sandbox sandbox;
    private final OutputGate gate;
    private final GradeStop stop;

    StudentGrade(GradeOptions options, Path sphere, Path renderer, GradeRange vplRange, Sandbox sandbox,
            GradeStop stop) {
        this.options = options;
        this.sphere = sphere;
        this.renderer = renderer;
        this.vplRange = vplRange;
        this.sandbox = sandbox;
        this.gate = stop.gate();
        this.stop = stop;
    }

    /** Grades, printing on {@code out} and {@code err} (the gate's); the exit status. */
    int call(PrintWriter out, PrintWriter err) throws IOException, InterruptedException {
        // What killed runs left (work folders that may hold hidden scenes, mounts, control groups) goes first.
        GradeCommand.reportUndeleted(Leftovers.remove(), err);
        Path work = Leftovers.newWorkFolder("grade");
        StudentProcess process = new StudentProcess(sandbox, work.resolve("harness"), options.memoryMegabytes());
        // On Ctrl-C or SIGTERM: say so, stop the student's process and delete the work folder, scenes and all.
        stop.onStop(() -> {
            gate.shutSaying(STOPPED_LINE);
            process.stop();
            GradeCommand.reportUndeleted(WorkFolder.delete(work), gate.past());
        });
        try {
            return grade(work, process, out, err);
        } catch (InterruptedException e) {
            // Ctrl-C or SIGTERM stopped the student's process: the grade's end, not a fault of tick1's (said
            // by the stop, whose gate drops this).
            throw new CommandFailure(GradeCommand.EXIT_STOPPED, STOPPED);
        } finally {
            stop.end(() -> {
                process.stop();
                GradeCommand.reportUndeleted(WorkFolder.delete(work), err);
            });
        }
    }

    private int grade(Path work, StudentProcess process, PrintWriter out, PrintWriter err)
            throws IOException, InterruptedException {
        Grading grading;
        Submission submission;
        try {
            sandbox.checkReachable(work);
            grading = Grading.prepare(work, options.scenesFolder(), options.limits());
            grading.copyScenes(work);
            grading.renderReferencesAhead();
            submission = vpl() ? StudentFiles.asSubmitted(sphere, renderer, err)
                    : StudentFiles.of(sphere, renderer, err);
            if (!vpl()) {
                WorkFolder.removeEarlierReport(options.reportFolder());
            }
        } catch (SceneException e) {
            throw new CommandFailure(GradeCommand.EXIT_USAGE, e.getMessage());
        } catch (IOException e) {
            throw new CommandFailure(GradeCommand.EXIT_USAGE, IoErrors.describe(e));
        }
        StudentProcess.writeHarness(Files.createDirectory(work.resolve("harness")));
        SubmissionGrader grader = new SubmissionGrader(grading, sandbox, process, work);
        // VPL adds up the memory of every process: its hidden run waits until this JVM has explained the public
        // scenes. A grade of tick1's own runs it beside that explaining.
        SubmissionGrader.Graded graded = vpl() ? grader.grade(submission, work, work.resolve("images"),
                new PrintWriter(Writer.nullWriter()), err)
                : grader.gradeWithHiddenRunAhead(submission, work, options.reportFolder(), out, err);
        if (vpl()) {
            out.print(VplReport.of(graded.result(), graded.compileErrors(), vplRange));
            out.flush();
        }
        if (graded.result().passed()) {
            return GradeCommand.EXIT_PASS;
        }
        return graded.imagesUnwritable() ? GradeCommand.EXIT_CANNOT_WRITE : GradeCommand.EXIT_FAIL;
    }

    private boolean vpl() {
        return vplRange != null;
    }
}
