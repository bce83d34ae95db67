package gfx.tick1.command.starter;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.grader.harness.StudentCompiler;
import gfx.tick1.command.shared.grader.intake.StudentFile;
import gfx.tick1.command.shared.kit.StarterKit;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
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

    /** The handout's section 2: what extracting tick1.zip shows. */
    private static final List<String> HANDOUTS_TREE = List.of("tick1/src/gfx/tick1/Camera.java",
            "tick1/src/gfx/tick1/PointLight.java", "tick1/src/gfx/tick1/Ray.java",
            "tick1/src/gfx/tick1/RaycastHit.java",
            "tick1/src/gfx/tick1/Renderer.java", "tick1/src/gfx/tick1/Scene.java",
            "tick1/src/gfx/tick1/SceneLoader.java", "tick1/src/gfx/tick1/Sphere.java", "tick1/src/gfx/tick1/Tick1.java",
            "tick1/src/gfx/tick1/Vector3.java", "tick1/basic_scene.xml");

    @Test
    void withoutOutTheKitIsTheHandoutsFolderTick1() throws Exception {
        CliRun run = CliRun.inFolder(dir, "starter");
        assertThat(run.status()).as(run.transcript()).isZero();
        try (Stream<Path> files = Files.walk(dir)) {
            assertThat(files.filter(Files::isRegularFile).map(file -> dir.relativize(file).toString()))
                    .as("the files written").containsExactlyInAnyOrderElementsOf(HANDOUTS_TREE);
        }
    }

    @Test
    void zipWritesTheHandoutsTick1ZipWhichUnpacksToTick1() throws IOException {
        Path zip = dir.resolve("tick1.zip");
        CliRun run = CliRun.of("starter", "--zip", zip.toString());
        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(run.out()).as("what it says it wrote").contains(zip + ", which unpacks to tick1/");
        Map<String, String> files = new LinkedHashMap<>();
        List<String> folders = new ArrayList<>();
        try (ZipInputStream in = new ZipInputStream(Files.newInputStream(zip))) {
            for (ZipEntry entry = in.getNextEntry(); entry != null; entry = in.getNextEntry()) {
                if (entry.isDirectory()) {
                    folders.add(entry.getName());
                } else {
                    files.put(entry.getName(), new String(in.readAllBytes(), StandardCharsets.UTF_8));
                }
            }
        }
        assertThat(files.keySet()).as("the zip's files").containsExactlyInAnyOrderElementsOf(HANDOUTS_TREE);
        assertThat(folders).as("the zip's folders, so that any unzip makes them")
                .containsExactly("tick1/", "tick1/src/", "tick1/src/gfx/", "tick1/src/gfx/tick1/");
        for (StarterKit.KitFile file : StarterKit.files()) {
            assertThat(files.get("tick1/" + file.path())).as(file.path()).isEqualTo(file.content());
        }
        assertThat(dir).as("nothing but the zip").isDirectoryNotContaining(path -> !path.equals(zip));
    }

    @Test
    void zipRefusesToOverwriteAFileUnlessForced() throws IOException {
        Path zip = Files.writeString(dir.resolve("tick1.zip"), "staff's own zip");
        CliRun again = CliRun.of("starter", "--zip", zip.toString());
        assertThat(again.status()).isEqualTo(StarterCommand.EXIT_WOULD_OVERWRITE);
        assertThat(again.err()).contains("already exists; use --force");
        assertThat(zip).content().isEqualTo("staff's own zip");
        assertThat(CliRun.of("starter", "--zip", zip.toString(), "--force").status()).isZero();
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

    /** tick1's own Sphere.java and Renderer.java, as a student's: the starter's package; they compile with the kit. */
    @Test
    void tick1sOwnSolutionInTheStartersPackageCompilesWithTheKit() throws Exception {
        List<StudentCompiler.Source> sources = new ArrayList<>();
        for (String name : StarterKit.GIVEN_CLASSES) {
            sources.add(new StudentCompiler.Source(name, name + ".java", StarterKit.source(name)));
        }
        for (String name : StarterKit.STUDENT_CLASSES) {
            String solution = StarterKit.solution(name);
            assertThat(solution).as(name).startsWith("package gfx.tick1;").doesNotContain("import gfx.tick1.")
                    .doesNotContain("TODO");
            sources.add(new StudentCompiler.Source(name, name + ".java", solution));
        }
        StudentCompiler.Result result = new StudentCompiler().compile(sources);
        assertThat(result.errors()).as("javac's errors").isEmpty();
        assertThat(result.classes()).containsKeys("gfx.tick1.Sphere", "gfx.tick1.Renderer", "gfx.tick1.Tick1");
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
