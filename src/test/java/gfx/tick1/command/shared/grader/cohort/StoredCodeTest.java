package gfx.tick1.command.shared.grader.cohort;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.lookalike.ComparedCode;
import gfx.tick1.command.shared.grader.lookalike.ParsedCode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Arrays;
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

    @Test
    void aFileCutShortAnywhereIsTheCodeKeptOrNoCodeNeverOtherCode(@TempDir Path dir) throws IOException {
        StoredCode store = new StoredCode(dir.resolve("parsed"), "build 1");
        Path file = keep(store, dir);
        byte[] whole = Files.readAllBytes(file);

        for (int length = 0; length < whole.length; length++) {
            Files.write(file, Arrays.copyOf(whole, length));
            // Cut after the last line's value, only the line's end is lost.
            assertThat(store.get("abc")).as("the code read from the file cut to %d of its %d bytes", length,
                    whole.length).isIn(Arrays.asList(CODE, null));
        }
    }

    @Test
    void aFileWhoseCountOfMembersIsChangedIsNoCode(@TempDir Path dir) throws IOException {
        StoredCode store = new StoredCode(dir.resolve("parsed"), "build 1");
        Path file = keep(store, dir);
        Files.writeString(file, Files.readString(file).replaceFirst("(?m)^members=2$", "members=-2147483648"));

        assertThat(store.get("abc")).as("the code read from a file that counts -2147483648 members").isNull();
    }

    @Test
    void theCodeOfOneDigestKeptUnderAnothersIsNoCode(@TempDir Path dir) throws IOException {
        StoredCode store = new StoredCode(dir.resolve("parsed"), "build 1");
        Path file = keep(store, dir);
        Path kept = dir.resolve("kept");
        Files.move(file, kept);
        store.put("def", new ParsedCode(List.of(), List.of()));
        Files.copy(kept, onlyFile(dir.resolve("parsed")), StandardCopyOption.REPLACE_EXISTING);

        assertThat(store.get("def")).as("the code of abc, found in the file of def").isNull();
    }

    @Test
    void codeTooLongToKeepIsParsedAgainNotKept(@TempDir Path dir) throws IOException {
        StoredCode store = new StoredCode(dir.resolve("parsed"), "build 1");
        store.put("abc", new ParsedCode(List.of(new ComparedCode.Member("Sphere.java", "deep()",
                " ".repeat(StoredCode.MOST_CHARACTERS + 1))), List.of()));

        try (Stream<Path> files = Files.list(dir.resolve("parsed"))) {
            assertThat(files.toList()).as("the files kept").isEmpty();
        }
    }

    /** Keeps {@link #CODE} under "abc" in {@code store}, in {@code dir}'s folder "parsed": its file. */
    private static Path keep(StoredCode store, Path dir) throws IOException {
        store.put("abc", CODE);
        return onlyFile(dir.resolve("parsed"));
    }

    private static Path onlyFile(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            List<Path> all = files.toList();
            assertThat(all).as("the files kept").hasSize(1);
            return all.get(0);
        }
    }
}
