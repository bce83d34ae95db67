package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The loader's limits keep every legal scene within a 1 GiB heap (Java's default on a machine with
 * 4 GiB of memory), DOM and all: the largest scenes each limit allows load in a JVM given no more.
 */
@Order(16)   // one of the longest classes: it starts early (junit-platform.properties)
class SceneLoaderMemoryTest {

    private static final String HEAP = "-Xmx1g";

    @TempDir
    Path dir;

    /** As many spheres as the element limit allows, each with all five attributes. */
    private Path sceneAtTheElementLimit() throws IOException {
        Path scene = dir.resolve("most-elements.xml");
        try (BufferedWriter out = Files.newBufferedWriter(scene, StandardCharsets.UTF_8)) {
            out.write("<scene>\n<point-light x='1' y='3' z='2' colour='#FFFFFF' intensity='100'/>\n");
            for (int i = 2; i < SceneLoader.MAX_ELEMENTS; i++) {
                out.write(String.format(Locale.ROOT,
                        "<sphere x='%.3f' y='%.3f' z='%d' radius='0.0125' colour='#%06X'/>\n",
                        (i % 997) / 997.0 - 0.5, (i % 991) / 991.0 - 0.5, 5 + i % 7, i & 0xFFFFFF));
            }
            out.write("</scene>\n");
        }
        assertThat(Files.size(scene)).isLessThanOrEqualTo(SceneLoader.MAX_FILE_BYTES);
        return scene;
    }

    /** A file of the largest size allowed, nearly all of it kept as attribute values. */
    private Path sceneAtTheSizeLimit() throws IOException {
        Path scene = dir.resolve("most-bytes.xml");
        String sphere = "<sphere x='0." + "1".repeat(4000) + "' z='5' radius='0.1' colour='#FF0000'/>\n";
        long spheres = (SceneLoader.MAX_FILE_BYTES - 100) / sphere.length();
        try (BufferedWriter out = Files.newBufferedWriter(scene, StandardCharsets.UTF_8)) {
            out.write("<scene>\n");
            for (long i = 0; i < spheres; i++) {
                out.write(sphere);
            }
            out.write("</scene>\n");
        }
        assertThat(Files.size(scene)).isGreaterThan(SceneLoader.MAX_FILE_BYTES - sphere.length() - 100)
                .isLessThanOrEqualTo(SceneLoader.MAX_FILE_BYTES);
        return scene;
    }

    /**
     * A file of the largest size allowed, of spheres with as many short attributes the format does
     * not have as fit: the most attributes a legal file can hold, each one only a warning.
     */
    private Path sceneOfShortUnknownAttributes() throws IOException {
        Path scene = dir.resolve("most-attributes.xml");
        StringBuilder attributes = new StringBuilder();
        for (int i = 0; i < 60; i++) {
            attributes.append(" q").append(i).append("='1'");
        }
        String sphere = "<sphere z='5' colour='#FF0000'" + attributes + "/>\n";
        long spheres = Math.min(SceneLoader.MAX_ELEMENTS - 3, (SceneLoader.MAX_FILE_BYTES - 100) / sphere.length());
        try (BufferedWriter out = Files.newBufferedWriter(scene, StandardCharsets.UTF_8)) {
            out.write("<scene>\n<point-light colour='#FFFFFF'/>\n");
            for (long i = 0; i < spheres; i++) {
                out.write(sphere);
            }
            out.write("</scene>\n");
        }
        assertThat(Files.size(scene)).isLessThanOrEqualTo(SceneLoader.MAX_FILE_BYTES);
        return scene;
    }

    /** Loads each scene in a JVM with {@code heap}, and returns what it printed; it must exit 0. */
    private String loadInAnotherJvm(String heap, Path... scenes) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> command = new ArrayList<>(List.of(java,
                heap, "-XX:+UseSerialGC", "-cp", System.getProperty("java.class.path"), Load.class.getName()));
        for (Path scene : scenes) {
            command.add(scene.toString());
        }
        Path output = dir.resolve("output.txt");
        Process process = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output.toFile()).start();
        boolean finished = process.waitFor(5, TimeUnit.MINUTES);
        if (!finished) {
            process.destroyForcibly().waitFor();
        }
        String printed = Files.readString(output, StandardCharsets.UTF_8);
        assertThat(finished).as("the loads finished within 5 minutes; so far the JVM printed:%n%s", printed).isTrue();
        assertThat(process.exitValue()).as("exit status of loading the scenes with %s; it printed:%n%s", heap, printed)
                .isZero();
        return printed;
    }

    @Test
    void theLargestLegalScenesLoadInOneGibibyteOfHeap() throws Exception {
        String printed = loadInAnotherJvm(HEAP, sceneAtTheElementLimit(), sceneAtTheSizeLimit(),
                sceneOfShortUnknownAttributes());

        assertThat(printed).contains("most-elements.xml: " + (SceneLoader.MAX_ELEMENTS - 2) + " spheres")
                .containsPattern("most-bytes.xml: [0-9]+ spheres")
                .containsPattern("most-attributes.xml: [0-9]+ spheres");
    }

    /** The other JVM of the test above: loads each scene in turn, saying how many spheres or why not. */
    static final class Load {
        public static void main(String[] args) {
            for (String file : args) {
                try {
                    Scene scene = new SceneLoader(Path.of(file), false).getScene();
                    System.out.println(Path.of(file).getFileName() + ": " + scene.getObjects().size() + " spheres");
                } catch (SceneException e) {
                    System.out.println(e.getMessage());
                }
            }
        }
    }
}
