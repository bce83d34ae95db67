package gfx.tick1.grade;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;

/**
 * Runs compiled student code in a separate JVM ({@link StudentHarness}) with a memory limit and a
 * time limit, so that an infinite loop, a crash, or a call to System.exit in the student's code is
 * reported and never inherited. The child is the same Java as this program, started with
 * {@code -Xmx}; on the time limit it is killed with everything it started.
 */
public final class StudentProcess {

    static final String PROGRESS_FILE = "progress";
    /** How much of what the student's code printed is kept, from the end. */
    private static final int OUTPUT_TAIL_CHARS = 2000;

    /** What became of one scene. */
    public sealed interface Outcome {
        /** The student's code rendered this image. */
        record Rendered(BufferedImage image) implements Outcome {
        }

        /** No image: why, in words for the student. */
        record Failed(String reason) implements Outcome {
        }
    }

    /** The outcome of every scene in order, and the last of what the student's code printed. */
    public record Result(List<Outcome> outcomes, String outputTail) {
    }

    private final Duration timeLimit;
    private final int memoryMegabytes;

    public StudentProcess(Duration timeLimit, int memoryMegabytes) {
        this.timeLimit = timeLimit;
        this.memoryMegabytes = memoryMegabytes;
    }

    /**
     * Renders each scene with the student's classes in {@code classes}; {@code work} is an empty
     * folder for the child's images and logs.
     */
    public Result render(Path classes, Path work, int width, int height, List<Path> scenes)
            throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + memoryMegabytes + "m",
                "-XX:+UseSerialGC",               // one GC thread: the student's code is single-threaded
                "-XX:TieredStopAtLevel=1",        // quick start; small renders are over before C2 pays
                "-Djava.awt.headless=true",
                "-cp", harnessClassPath(),
                StudentHarness.class.getName(),
                classes.toAbsolutePath().toString(), work.toAbsolutePath().toString(),
                Integer.toString(width), Integer.toString(height)));
        scenes.forEach(scene -> command.add(scene.toAbsolutePath().toString()));

        Process process = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectInput(ProcessBuilder.Redirect.PIPE).start();
        process.getOutputStream().close();
        OutputTail tail = new OutputTail(process.getInputStream());
        tail.start();
        boolean finished = process.waitFor(timeLimit.toMillis(), TimeUnit.MILLISECONDS);
        if (!finished) {
            process.descendants().forEach(ProcessHandle::destroyForcibly);
            process.destroyForcibly();
            process.waitFor();
        }
        tail.join(1000);

        List<String> progress = Files.exists(work.resolve(PROGRESS_FILE))
                ? Files.readAllLines(work.resolve(PROGRESS_FILE), StandardCharsets.UTF_8) : List.of();
        List<Outcome> outcomes = new ArrayList<>();
        for (int i = 0; i < scenes.size(); i++) {
            outcomes.add(outcome(work, i, progress, finished, process.exitValue()));
        }
        return new Result(outcomes, tail.text());
    }

    /**
     * Where this program's classes are (its jar, or a classes folder in a build): the harness needs
     * nothing else, and java.class.path is not it under every launcher (test runners, IDEs).
     */
    private static String harnessClassPath() throws IOException {
        try {
            return Path.of(StudentHarness.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (java.net.URISyntaxException | RuntimeException e) {
            throw new IOException("cannot find this program's own classes to run the student's code with", e);
        }
    }

    private Outcome outcome(Path work, int index, List<String> progress, boolean finished, int exitStatus)
            throws IOException {
        Path image = work.resolve(index + ".png");
        Path error = work.resolve(index + ".error");
        if (Files.exists(error)) {
            return new Outcome.Failed("the code threw " + Files.readString(error, StandardCharsets.UTF_8));
        }
        if (progress.contains("end " + index) && Files.exists(image)) {
            BufferedImage picture = ImageIO.read(image.toFile());
            if (picture != null) {
                return new Outcome.Rendered(picture);
            }
        }
        if (!progress.contains("start " + index)) {
            return new Outcome.Failed("not rendered: the run stopped at an earlier scene");
        }
        if (!finished) {
            return new Outcome.Failed("no image within the time limit of " + describe(timeLimit)
                    + " (an infinite loop?); the program was stopped");
        }
        return new Outcome.Failed("the program ended while rendering this scene, with exit status " + exitStatus
                + (exitStatus == 0 ? " (does the code call System.exit?)" : " (System.exit, or the JVM crashed)"));
    }

    private static String describe(Duration duration) {
        long millis = duration.toMillis();
        return millis % 1000 == 0 ? millis / 1000 + " s" : millis / 1000.0 + " s";
    }

    /** Reads the child's output as it comes, keeping only the end, so no output can fill memory. */
    private static final class OutputTail extends Thread {
        private final InputStream in;
        private final StringBuilder text = new StringBuilder();

        OutputTail(InputStream in) {
            this.in = in;
            setDaemon(true);
        }

        @Override
        public void run() {
            byte[] buffer = new byte[8192];
            try {
                for (int n; (n = in.read(buffer)) > 0; ) {
                    synchronized (text) {
                        text.append(new String(buffer, 0, n, StandardCharsets.UTF_8));
                        if (text.length() > 2 * OUTPUT_TAIL_CHARS) {
                            text.delete(0, text.length() - OUTPUT_TAIL_CHARS);
                        }
                    }
                }
            } catch (IOException e) {
                // The child was killed: what was read is all there is.
            }
        }

        String text() {
            synchronized (text) {
                return text.length() > OUTPUT_TAIL_CHARS ? text.substring(text.length() - OUTPUT_TAIL_CHARS)
                        : text.toString();
            }
        }
    }
}
