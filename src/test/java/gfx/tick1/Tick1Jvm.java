package gfx.tick1;

import gfx.tick1.command.shared.cli.MainClass;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
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
 * class data sharing archive of the classes a grade loads. Such a JVM finds those classes already parsed and
 * verified instead of reading each from the build's folders, and the tests start many.
 *
 * <p>Java 17 archives no class read from a folder, so the class path's folders (the build's classes and resources,
 * main's and the tests') are put in one jar, at the first folder's place, a name in an earlier folder hiding the
 * same name in a later one as on the class path; where a jar comes between two folders the order could not be
 * kept, and tick1 starts from the class path as it is. The archive is dynamic, written at the end of a grade of
 * the course's correct solution: unlike the installed launcher's static one, it leaves out the classes of old
 * bytecode (picocli's annotations), which load from the jar as before. Both are made once, the first time a test
 * asks, in build/tick1-jvm-PID, which {@link WorkFolder#delete} removes when the tests' JVM ends (or the next run
 * does, when it was killed). Where the jar cannot be made, tick1 starts from the class path as it is; where the
 * archive cannot, from the jar alone; a JVM that cannot map the archive starts without it, silently.
 *
 * <p>A cohort's stored results are keyed by the code that graded them, here the jar: a grade resumed in the tests'
 * own JVM, which reads the folders, grades again what a tick1 started so had stored.
 */
public final class Tick1Jvm {

    /** The folder the jar and the archive are made in, under the folder the tests run in (the project's). */
    private static final Path UNDER = Path.of("build");
    private static final String FOLDER_PREFIX = "tick1-jvm-";
    /** How long the run that makes the archive may take: a grade of a tiny image, on a busy machine. */
    private static final int ARCHIVE_RUN_SECONDS = 120;
    /** The course's correct solution, which the run that makes the archive grades. */
    private static final String STUDENT = "/students/correct/";

    private static List<String> made;

    private Tick1Jvm() {
    }

    /**
     * The arguments after the test's JVM options that start tick1: the harness's archive that the tests' grades map
     * ({@link HarnessArchiveSession}), when there is one; this class's archive; the class path and the main class.
     */
    public static synchronized List<String> mainClass() {
        if (made == null) {
            made = make();
        }
        String harnessArchive = System.getProperty(StudentProcess.KEPT_ARCHIVE_PROPERTY);
        if (harnessArchive == null) {
            return made;
        }
        List<String> arguments = new ArrayList<>(List.of("-D" + StudentProcess.KEPT_ARCHIVE_PROPERTY + "="
                + harnessArchive));
        arguments.addAll(made);
        return List.copyOf(arguments);
    }

    private static List<String> make() {
        List<String> asItIs = List.of("-cp", System.getProperty("java.class.path"), MainClass.NAME);
        try {
            Path folder = freshFolder();
            Runtime.getRuntime().addShutdownHook(new Thread(() -> WorkFolder.delete(folder)));
            String classPath = jarredClassPath(folder.resolve("classes.jar"));
            if (classPath == null) {
                return asItIs;
            }
            Path archive = folder.resolve("tick1.jsa");
            List<String> arguments = new ArrayList<>();
            if (archived(archive, classPath, folder)) {
                arguments.addAll(List.of("-XX:SharedArchiveFile=" + archive, "-Xlog:cds=off",
                        "-Xlog:cds+dynamic=off"));
            }
            arguments.addAll(List.of("-cp", classPath, MainClass.NAME));
            return List.copyOf(arguments);
        } catch (IOException | UncheckedIOException e) {
            return asItIs;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return asItIs;
        }
    }

    /** build/tick1-jvm-PID, empty, after removing those of test runs that have ended. */
    private static Path freshFolder() throws IOException {
        Path under = Files.createDirectories(UNDER).toAbsolutePath();
        try (Stream<Path> folders = Files.list(under)) {
            for (Path old : folders.filter(path -> path.getFileName().toString().startsWith(FOLDER_PREFIX)).toList()) {
                String pid = old.getFileName().toString().substring(FOLDER_PREFIX.length());
                // Another run's while its JVM lives; an ended run's, or this pid's from a run before, goes.
                if (!pid.matches("[0-9]{1,18}") || ProcessHandle.of(Long.parseLong(pid))
                        .filter(process -> process.pid() != ProcessHandle.current().pid()).isEmpty()) {
                    WorkFolder.delete(old);
                }
            }
        }
        return Files.createDirectory(under.resolve(FOLDER_PREFIX + ProcessHandle.current().pid()));
    }

    /**
     * The class path with its folders in one jar, written to {@code jar}, at the first folder's place; null when a
     * jar comes between two folders, where one jar could not keep their order.
     */
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
                } else if (!entries.get(entries.size() - 1).equals(jar.toString())) {
                    return null;
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
        Path student = Files.createDirectory(folder.resolve("student"));
        for (String name : List.of("Sphere.java", "Renderer.java")) {
            try (InputStream in = Tick1Jvm.class.getResourceAsStream(STUDENT + name)) {
                if (in == null) {
                    return false;
                }
                Files.copy(in, student.resolve(name));
            }
        }
        List<String> command = CliRun.java();
        command.addAll(List.of("-XX:ArchiveClassesAtExit=" + archive, "-Xlog:cds=off", "-Xlog:cds+dynamic=off",
                "-cp", classPath, MainClass.NAME, "grade",
                "--sphere", student.resolve("Sphere.java").toString(),
                "--renderer", student.resolve("Renderer.java").toString(),
                "--report", folder.resolve("report").toString(), "--width", "16", "--height", "12"));
        Process process = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(folder.resolve("archive-run.log").toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null"))).start();
        try {
            if (!process.waitFor(ARCHIVE_RUN_SECONDS, TimeUnit.SECONDS)) {
                return false;
            }
        } finally {
            // Stopped as a user's Ctrl-C stops it, so that the grade removes its work folder and mounts.
            if (process.isAlive()) {
                process.destroy();
                if (!process.waitFor(30, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                }
            }
        }
        return Files.isRegularFile(archive) && Files.size(archive) > 0;
    }
}
