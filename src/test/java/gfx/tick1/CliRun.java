package gfx.tick1;

import gfx.tick1.command.render.RenderCommand;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine;

/**
 * One run of the real entry point with what it printed captured: the text on standard output
 * and error, and the bytes written to standard output (the image, for {@code -o -}).
 */
public record CliRun(int status, String out, String err, byte[] stdout) {

    /** How long a tick1 in a JVM of its own may take: far more than any test's command needs, so a hang fails. */
    private static final int MINUTES_AT_MOST = 10;

    public static CliRun of(String... args) {
        ByteArrayOutputStream binary = new ByteArrayOutputStream();
        StringWriter out = new StringWriter(), err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new RenderCommand(binary));
        commandLine.setOut(new PrintWriter(out, true));
        commandLine.setErr(new PrintWriter(err, true));
        int status = commandLine.execute(args);
        return new CliRun(status, out.toString(), err.toString(), binary.toByteArray());
    }

    /**
     * One run of tick1 in a fresh process whose current folder is {@code folder}, as a user runs it
     * there: relative names (the defaults basic_scene.xml and output.png among them) mean files of
     * that folder. {@link #stdout} is empty; the image is never wanted on standard output here.
     */
    public static CliRun inFolder(Path folder, String... args) throws IOException, InterruptedException {
        return inJvm(folder, List.of(), args);
    }

    /**
     * As {@link #inFolder}, in a JVM also given {@code jvmOptions}: a system property that only this run reads (the
     * tests' own JVM, where other classes' tests run, keeps its own).
     */
    public static CliRun inJvm(Path folder, List<String> jvmOptions, String... args)
            throws IOException, InterruptedException {
        List<String> command = java();
        command.addAll(jvmOptions);
        command.addAll(Tick1Jvm.mainClass());
        command.addAll(List.of(args));
        Path out = Files.createTempFile("tick1-out", ".txt"), err = Files.createTempFile("tick1-err", ".txt");
        try {
            Process process = new ProcessBuilder(command).directory(folder.toFile())
                    .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                    .redirectOutput(out.toFile()).redirectError(err.toFile()).start();
            if (!process.waitFor(MINUTES_AT_MOST, TimeUnit.MINUTES)) {
                process.destroyForcibly().waitFor();
                throw new AssertionError("tick1 " + String.join(" ", args) + " did not end within " + MINUTES_AT_MOST
                        + " minutes, and was killed; it printed:\n" + Files.readString(out) + Files.readString(err));
            }
            return new CliRun(process.exitValue(), Files.readString(out), Files.readString(err), new byte[0]);
        } finally {
            Files.delete(out);
            Files.delete(err);
        }
    }

    /**
     * The start of the command line of a JVM of its own that a test runs tick1 in: this JDK's java with the serial
     * collector and only the JIT's first tier, as the installed launcher starts a small render. A test's grade or
     * render in it lasts seconds, in which the second tier's compiling would cost more processor time than it saves.
     */
    public static List<String> java() {
        return new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1"));
    }

    /** Everything printed, for assertion messages. */
    public String transcript() {
        return "exit " + status + "\n--- out:\n" + out + "--- err:\n" + err;
    }
}
