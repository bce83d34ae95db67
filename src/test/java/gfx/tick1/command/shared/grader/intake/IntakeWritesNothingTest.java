package gfx.tick1.command.shared.grader.intake;

import static gfx.tick1.command.shared.grader.intake.TestZips.entries;
import static gfx.tick1.command.shared.grader.intake.TestZips.zip;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The intake writes nothing to disk, whatever it reads: every kind of download, ordinary and hostile, is read in a
 * JVM of its own whose temporary folder and working folder start empty, and they, and the downloads, are checked
 * after. (A JVM of its own, because this JVM's temporary folder is shared with everything else running.)
 */
class IntakeWritesNothingTest {

    private static final String SPHERE = "package gfx.tick1;\nclass Sphere {}\n";

    @TempDir
    Path temp;

    @Test
    void readingAnyDownloadCreatesNoFileAnywhere() throws Exception {
        Path downloads = Files.createDirectory(temp.resolve("downloads"));
        byte[] nested = zip(entries("src/Sphere.java", SPHERE, "src/Renderer.java", SPHERE));
        byte[] slip = new TestZips.Raw().add("s/../../x", "x").bytes();
        byte[] name = "s/Sphere.java".getBytes(StandardCharsets.UTF_8);
        Map<String, byte[]> archives = new TreeMap<>(Map.of(
                "ordinary.zip", zip(entries("a_1_assignsubmission_file_/Sphere.java", SPHERE,
                        "a_1_assignsubmission_file_/Renderer.java", SPHERE, "b/w.zip", nested, "c/", "")),
                "slip.zip", slip,
                "slip-inside.zip", zip(entries("s/w.zip", slip)),
                "link.zip", new TestZips.Raw().symlink("s/Sphere.java", "/etc/passwd").bytes(),
                "bomb.zip", new TestZips.Raw().add(name, name, new byte[4 << 20], true, 10, 0, 0).bytes(),
                "duplicate.zip", new TestZips.Raw().add("s/a", "1").add("s/a", "2").bytes(),
                "not-a-zip.zip", "plain text".getBytes(StandardCharsets.UTF_8)));
        for (Map.Entry<String, byte[]> archive : archives.entrySet()) {
            Files.write(downloads.resolve(archive.getKey()), archive.getValue());
        }
        Path folder = Files.createDirectories(downloads.resolve("unpacked/s"));
        Files.write(folder.resolve("w.zip"), nested);
        Files.createSymbolicLink(folder.resolve("Renderer.java"), downloads.resolve("ordinary.zip"));
        Path tmp = Files.createDirectory(temp.resolve("tmp"));
        Path work = Files.createDirectory(temp.resolve("work"));
        Map<String, String> before = snapshot(downloads);

        List<String> command = new ArrayList<>(List.of(Paths.get(System.getProperty("java.home"), "bin", "java")
                .toString(), "-Djava.io.tmpdir=" + tmp, "-cp", System.getProperty("java.class.path"),
                Probe.class.getName()));
        try (Stream<Path> all = Files.list(downloads)) {
            all.sorted().map(Path::toString).forEach(command::add);
        }
        Process probe = new ProcessBuilder(command).directory(work.toFile()).redirectErrorStream(true).start();
        String output = new String(probe.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(probe.waitFor(2, TimeUnit.MINUTES)).isTrue();

        assertThat(output).as("the probe read every download").contains("ordinary.zip: 3 submissions")
                .contains("unpacked: 1 submissions").contains("slip.zip: refused");
        assertThat(snapshot(tmp)).as("the temporary folder").isEmpty();
        assertThat(snapshot(work)).as("the working folder").isEmpty();
        assertThat(snapshot(downloads)).as("the downloads").isEqualTo(before);
    }

    /** Every path below the folder, with its size and time of change (links not followed). */
    private static Map<String, String> snapshot(Path folder) throws IOException {
        Map<String, String> files = new TreeMap<>();
        try (Stream<Path> all = Files.walk(folder)) {
            for (Path path : (Iterable<Path>) all::iterator) {
                if (!path.equals(folder)) {
                    files.put(folder.relativize(path).toString(), Files.isSymbolicLink(path) ? "link"
                            : Files.size(path) + "@" + Files.getLastModifiedTime(path));
                }
            }
        }
        return files;
    }

    /** Reads each download named on the command line and says what came of it. */
    static final class Probe {
        private Probe() {
        }

        public static void main(String[] args) {
            for (String arg : args) {
                Path path = Paths.get(arg);
                try {
                    System.out.println(path.getFileName() + ": " + Submissions.read(path).size() + " submissions");
                } catch (IOException e) {
                    System.out.println(path.getFileName() + ": refused: " + e.getMessage());
                }
            }
        }
    }
}
