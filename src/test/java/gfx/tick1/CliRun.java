package gfx.tick1;

import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import picocli.CommandLine;

/**
 * One run of the real entry point with what it printed captured, for the subcommands' tests in
 * other packages (Tick1CommandTest has its own for the render command).
 */
public record CliRun(int status, String out, String err) {

    public static CliRun of(String... args) {
        StringWriter out = new StringWriter(), err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new Tick1(new ByteArrayOutputStream()));
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        int status = commandLine.execute(args);
        return new CliRun(status, out.toString(), err.toString());
    }

    /** Everything printed, for assertion messages. */
    public String transcript() {
        return "exit " + status + "\n--- out:\n" + out + "--- err:\n" + err;
    }
}
