package gfx.tick1;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.stream.Stream;

/**
 * A test's own main class run in a JVM of its own whose temporary folder is a test's, to see what that JVM's end
 * leaves there: what it said, and the names left in the folder.
 */
public record EndedJvm(String said, List<Path> left) {

    /** Runs {@code main} with {@code temporary} as java.io.tmpdir, to its end (at most a minute). */
    public static EndedJvm of(Class<?> main, Path temporary) throws IOException, InterruptedException {
        List<String> command = CliRun.java();
        command.addAll(List.of("-Djava.io.tmpdir=" + temporary, "-cp", System.getProperty("java.class.path"),
                main.getName()));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String said = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new IllegalStateException(main.getSimpleName() + " did not end in a minute; it said: " + said);
        }
        try (Stream<Path> names = Files.list(temporary)) {
            return new EndedJvm(said, names.toList());
        }
    }

    /**
     * In the other JVM: ends it with System.exit as soon as a name in the temporary folder starting with
     * {@code prefix} passes {@code ready}, saying "ended during"; or, after {@code seconds}, says it never did.
     */
    public static void endOnceMade(String prefix, Predicate<Path> ready, int seconds)
            throws IOException {
        Path temporary = Path.of(System.getProperty("java.io.tmpdir"));
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (System.nanoTime() < end) {
            try (Stream<Path> names = Files.list(temporary)) {
                if (names.anyMatch(name -> name.getFileName().toString().startsWith(prefix) && ready.test(name))) {
                    System.out.println("ended during the work");
                    System.exit(0);
                }
            }
        }
        System.out.println(prefix + "... was never seen");
    }
}
