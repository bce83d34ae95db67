package gfx.tick1.fuzz;

import java.io.IOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Named;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The fuzz tests' two properties ({@link SceneFuzzTest}) on every file below the resource folder
 * gfx/tick1/fuzz/SceneFuzzTestInputs, each seed Jazzer starts from among them: the bad-input corpus, the
 * example scenes (the hard cases too) and any finding saved, which the build puts there.
 */
class SceneSeedsTest {

    /** Each seed, named by its path in the folder. */
    static List<Named<Path>> seeds() throws IOException, URISyntaxException {
        URL folder = SceneSeedsTest.class.getResource("SceneFuzzTestInputs");
        if (folder == null) {
            throw new IOException("the seeds' folder gfx/tick1/fuzz/SceneFuzzTestInputs is not on the class path");
        }
        Path root = Path.of(folder.toURI());
        try (Stream<Path> files = Files.walk(root)) {
            return files.filter(Files::isRegularFile).sorted()
                    .map(file -> Named.of(root.relativize(file).toString(), file)).toList();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("seeds")
    void theLoaderReturnsABoundedSceneOrOneLineError(Path seed) throws IOException {
        SceneFuzzTest.load(Files.readAllBytes(seed));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("seeds")
    void anySceneTheLoaderAcceptsRendersAndEncodes(Path seed) throws IOException {
        SceneFuzzTest.rendersAndEncodes(Files.readAllBytes(seed));
    }
}
