package gfx.tick1;

import gfx.tick1.command.shared.cli.MainClass;
import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;

/**
 * How a test starts tick1 in a JVM of its own, after the JVM's options: the class path and the main class, and a
 * class data sharing archive of the classes a grade loads, as the installed launcher maps its own. Such a JVM finds
 * tick1's classes already parsed and verified instead of reading each from the build's folders, and the tests
 * start many.
 *
 * <p>Java 17 archives no class read from a folder, so the class path's folders (the build's classes and resources,
 * main's and the tests') are put in one jar first, in their order, a name in an earlier folder hiding the same
 * name in a later one as on the class path. The jar and the archive are made once, the first time a test asks, in
 * a folder of build/ removed when the tests' JVM ends. Where either cannot be made, tick1 starts from the class
 * path as it is; a JVM that cannot map the archive starts without it, silently.
 *
 * <p>A cohort's stored results are keyed by the code that graded them, here the jar: a grade resumed in the tests'
 * own JVM, which reads the folders, grades again what a tick1 started so had stored.
 */
public final class Tick1Jvm {

    /** The folder both are made in, under the folder the tests run in (the project's). */
    private static final Path UNDER = Path.of("build");
    /** How long the run that makes the archive may take: a grade of a tiny image, on a busy machine. */
    private static final int ARCHIVE_RUN_SECONDS = 120;

    private static List<String> made;

    private Tick1Jvm() {
    }

    /** The arguments after the JVM's own options that start tick1: the archive's, the class path and the main class. */
    public static synchronized List<String> mainClass() {
        if (made == null) {
            made = make();
        }
        return made;
    }

    private static List<String> make() {
        try {
            Path folder = Files.createTempDirectory(Files.createDirectories(UNDER), "tick1-jvm-").toAbsolutePath();
            Runtime.getRuntime().addShutdownHook(new Thread(() -> deleteQuietly(folder)));
            String classPath = jarredClassPath(folder.resolve("classes.jar"));
            Path archive = folder.resolve("tick1.jsa");
            List<String> arguments = new ArrayList<>();
            if (archived(archive, classPath, folder)) {
                arguments.addAll(List.of("-XX:SharedArchiveFile=" + archive, "-Xlog:cds=off",
                        "-Xlog:cds+dynamic=off"));
            }
            arguments.addAll(List.of("-cp", classPath, MainClass.NAME));
            return List.copyOf(arguments);
        } catch (IOException | UncheckedIOException e) {
            return List.of("-cp", System.getProperty("java.class.path"), MainClass.NAME);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return List.of("-cp", System.getProperty("java.class.path"), MainClass.NAME);
        }
    }

    /** The class path with its folders, in order, in one jar (written to {@code jar}) at the first folder's place. */
    private static String jarredClassPath(Path jar) throws IOException {
        List<String> entries = new ArrayList<>();
        Set<String> names = new HashSet<>();
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            out.setLevel(0);   // stored: read once per JVM, and written in a moment
            for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
                Path path = Path.of(entry);
                if (!Files.isDirectory(path)) {
                    entries.add(entry);
                    continue;
                }
                if (!entries.contains(jar.toString())) {
                    entries.add(jar.toString());
                }
                try (Stream<Path> files = Files.walk(path)) {
                    for (Path file : files.filter(Files::isRegularFile).sorted().toList()) {
                        String name = path.relativize(file).toString().replace(File.separatorChar, '/');
                        if (names.add(name)) {
                            out.putNextEntry(new JarEntry(name));
                            Files.copy(file, out);   // leaves the jar open
                            out.closeEntry();
                        }
                    }
                }
            }
        }
        return String.join(File.pathSeparator, entries);
    }

    /**
     * Makes the archive: tick1 grades the course's correct solution at 16 x 12 pixels, loading the classes a grade
     * loads (where there is no sandbox, those up to its refusal), and writes them at its end.
     */
    private static boolean archived(Path archive, String classPath, Path folder)
            throws IOException, InterruptedException {
        Path student = Path.of("src/test/resources/students/correct").toAbsolutePath();
        List<String> command = CliRun.java();
        command.addAll(List.of("-XX:ArchiveClassesAtExit=" + archive, "-Xlog:cds=off", "-Xlog:cds+dynamic=off",
                "-cp", classPath, MainClass.NAME, "grade",
                "--sphere", student.resolve("Sphere.java").toString(),
                "--renderer", student.resolve("Renderer.java").toString(),
                "--report", folder.resolve("report").toString(), "--width", "16", "--height", "12"));
        Process process = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(folder.resolve("archive-run.log").toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null"))).start();
        if (!process.waitFor(ARCHIVE_RUN_SECONDS, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
            return false;
        }
        return Files.isRegularFile(archive) && Files.size(archive) > 0;
    }

    private static void deleteQuietly(Path folder) {
        try (Stream<Path> all = Files.walk(folder)) {
            all.sorted(java.util.Comparator.reverseOrder()).forEach(path -> path.toFile().delete());
        } catch (IOException | UncheckedIOException e) {
            // Left in build/, which the next clean removes.
        }
    }
}
