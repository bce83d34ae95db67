package gfx.tick1.command.shared.grader.cohort;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.lookalike.ComparedCode;
import gfx.tick1.command.shared.grader.lookalike.ParsedCode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The code the look-alike check parsed, kept in the report folder's state between runs. */
class StoredCodeTest {

    private static final ParsedCode CODE = new ParsedCode(List.of(
            new ComparedCode.Member("Sphere.java", "intersectionWith(Ray)", "double #1 = 0;\nreturn null; // Zoë\\n"),
            new ComparedCode.Member("Renderer.java", "helper(int)", "return #1 = \"a=b\";")),
            List.of("Renderer.java does not parse"));

    @Test
    void codeKeptIsReadBackAsItWasKept(@TempDir Path dir) throws IOException {
        new StoredCode(dir.resolve("parsed"), "build 1").put("abc", CODE);

        assertThat(new StoredCode(dir.resolve("parsed"), "build 1").get("abc")).as("the code read back")
                .isEqualTo(CODE);
    }

    @Test
    void anotherBuildOfTick1ParsesAgain(@TempDir Path dir) throws IOException {
        new StoredCode(dir.resolve("parsed"), "build 1").put("abc", CODE);

        assertThat(new StoredCode(dir.resolve("parsed"), "build 2").get("abc")).as("the code of another build")
                .isNull();
    }

    @Test
    void damagedCodeIsNoCode(@TempDir Path dir) throws IOException {
        StoredCode store = new StoredCode(dir.resolve("parsed"), "build 1");
        store.put("abc", CODE);
        try (Stream<Path> files = Files.list(dir.resolve("parsed"))) {
            for (Path file : files.toList()) {
                Files.writeString(file, "members=2\nmember.0.file=Sphere.java\n");
            }
        }

        assertThat(store.get("abc")).as("the code read from a damaged file").isNull();
    }
}
