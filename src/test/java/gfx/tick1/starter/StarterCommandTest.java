package gfx.tick1.starter;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.grade.harness.StudentCompiler;
import gfx.tick1.grade.harness.StudentFile;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class StarterCommandTest {

    @TempDir
    Path dir;

    @Test
    void writesTheHandoutsLayoutWithTheKitsContent() throws IOException {
        CliRun run = CliRun.of("starter", "--out", dir.toString());
        assertThat(run.status()).as(run.transcript()).isZero();
        for (StarterKit.KitFile file : StarterKit.files()) {
            assertThat(Files.readString(dir.resolve(file.path()))).as(file.path()).isEqualTo(file.content());
        }
        assertThat(StarterKit.files()).hasSize(11);
        assertThat(dir.resolve("src/gfx/tick1/Sphere.java")).content()
                .contains("TODO: Determine if ray and sphere intersect");
        assertThat(dir.resolve("src/gfx/tick1/Renderer.java")).content().contains("TODO: Calculate L, V, and R");
        assertThat(dir.resolve("basic_scene.xml")).content()
                .isEqualTo(Files.readString(Path.of("scenes/basic_scene.xml")));
    }

    @Test
    void theKitAsHandedOutCompiles() throws Exception {
        CliRun.of("starter", "--out", dir.toString());
        List<StudentCompiler.Source> sources = new ArrayList<>();
        try (Stream<Path> files = Files.list(dir.resolve("src/gfx/tick1"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).sorted().toList()) {
                String name = file.getFileName().toString().replace(".java", "");
                sources.add(new StudentCompiler.Source(name, file.toString(), StudentFile.read(file)));
            }
        }
        StudentCompiler.Result result = new StudentCompiler().compile(sources);
        assertThat(result.errors()).isEmpty();
        assertThat(result.classes()).containsKeys("gfx.tick1.Sphere", "gfx.tick1.Renderer", "gfx.tick1.Vector3",
                "gfx.tick1.SceneLoader", "gfx.tick1.Tick1");
    }

    @Test
    void refusesToOverwriteAnEarlierKitUnlessForced() throws IOException {
        CliRun.of("starter", "--out", dir.toString());
        Files.writeString(dir.resolve("src/gfx/tick1/Sphere.java"), "my work");
        CliRun again = CliRun.of("starter", "--out", dir.toString());
        assertThat(again.status()).isEqualTo(StarterCommand.EXIT_WOULD_OVERWRITE);
        assertThat(again.err()).contains("already exists; use --force");
        assertThat(dir.resolve("src/gfx/tick1/Sphere.java")).content().isEqualTo("my work");
        assertThat(CliRun.of("starter", "--out", dir.toString(), "--force").status()).isZero();
    }
}
