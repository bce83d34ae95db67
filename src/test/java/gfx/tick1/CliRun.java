package gfx.tick1;

import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import picocli.CommandLine;

/**
 * One run of the real entry point with what it printed captured: the text on standard output
 * and error, and the bytes written to standard output (the image, for {@code -o -}).
 */
public record CliRun(int status, String out, String err, byte[] stdout) {

    public static CliRun of(String... args) {
        ByteArrayOutputStream binary = new ByteArrayOutputStream();
        StringWriter out = new StringWriter(), err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new RenderCommand(binary));
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        int status = commandLine.execute(args);
        return new CliRun(status, out.toString(), err.toString(), binary.toByteArray());
    }

    /** Everything printed, for assertion messages. */
    public String transcript() {
        return "exit " + status + "\n--- out:\n" + out + "--- err:\n" + err;
    }
}
