package gfx.tick1.command.grade;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.grader.vpl.GradeRange;
import gfx.tick1.command.shared.grader.vpl.VplReport;
import java.io.IOException;
import java.io.PrintWriter;
import java.util.concurrent.Callable;

/**
 * {@code tick1 grade --format vpl}: one student's grade as VPL's evaluation. Where tick1 cannot grade (no
 * sandbox can be made, a file or a scene cannot be read), the report says so and proposes no grade, and the
 * reason goes, as ever, to the standard error, which the activity's vpl_evaluate.sh shows to staff. It never
 * runs the code without the sandbox: its hidden scenes and its report would be in the student's reach.
 */
final class VplGrade implements Callable<Integer> {

    private final GradeCommand command;
    private final PrintWriter out;
    private final PrintWriter err;

    VplGrade(GradeCommand command, PrintWriter out, PrintWriter err) {
        this.command = command;
        this.out = out;
        this.err = err;
    }

    /** Why the options do not go with --format vpl, or null. */
    static String checkOptions(GradeCommand command) {
        if (!command.oneStudent()) {
            return "--format vpl grades one student: give --sphere and --renderer";
        }
        if (command.noSandbox()) {
            return "--format vpl never runs a student's code without the sandbox: leave out --no-sandbox";
        }
        try {
            GradeRange.parse(command.gradeRangeText());
        } catch (IllegalArgumentException e) {
            return "--grade-range " + command.gradeRangeText() + ": " + e.getMessage();
        }
        return null;
    }

    @Override
    public Integer call() throws IOException, InterruptedException {
        try {
            return command.call(out, err);
        } catch (CommandFailure | IOException e) {
            out.print(VplReport.notSetUp());
            out.flush();
            throw e;
        }
    }
}
