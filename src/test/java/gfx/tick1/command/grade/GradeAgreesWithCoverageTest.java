package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.coverage.CatalogueOnScenes;
import gfx.tick1.command.shared.coverage.Coverage;
import gfx.tick1.command.shared.coverage.GradingScenes;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * tick1 coverage's numbers agree with grading: a student whose code is exactly a catalogued
 * mistake fails a scene if and only if coverage says the scene catches it. A few mistakes, on
 * scenes where some catch them and some do not, at 160 x 120 to keep it quick.
 */
@Order(11)   // one of the longest classes: it starts early (junit-platform.properties)
class GradeAgreesWithCoverageTest {

    @TempDir
    Path dir;

    static Stream<Arguments> mistakes() {
        StudentSolution correct = StudentSolution.correct();
        return Stream.of(
                Arguments.of(Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT, Mistakes.HIT_REJECTED_ON_A_NEGATIVE_ROOT),
                Arguments.of(Variant.NORMAL_NOT_NORMALISED, correct.editSphere(
                        "Vector3 normal = this.getNormalAt(point);", "Vector3 normal = point.subtract(position);")),
                Arguments.of(Variant.FAR_ROOT, correct.editSphere(Mistakes.NEAR_ROOT, "double s = s2;")));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("mistakes")
    void aStudentWhoseCodeIsTheMistakeFailsExactlyTheScenesCoverageSaysCatchIt(Variant mistake,
            StudentSolution solution) throws IOException, InterruptedException {
        try {
            Sandbox.confined();
        } catch (Sandbox.Unavailable e) {
            assumeThat(false).as("grading needs the bubblewrap sandbox: " + e.getMessage()).isTrue();
        }
        Path scenes = Files.createDirectory(dir.resolve("scenes"));
        Files.copy(Path.of("scenes/basic_scene.xml"), scenes.resolve("basic_scene.xml"));
        Files.copy(Path.of("scenes/hard/camera-inside-sphere.xml"), scenes.resolve("camera-inside-sphere.xml"));
        Coverage coverage = CatalogueOnScenes.measure(GradingScenes.withFolder(scenes), 160, 120);
        Path[] files = solution.writeTo(dir.resolve("student"));
        CliRun run = CliRun.of("grade", "--sphere", files[0].toString(), "--renderer", files[1].toString(),
                "--report", dir.resolve("report").toString(), "--scenes", scenes.toString(), "--width", "160",
                "--height", "120");
        List<String> lines = run.out().lines().toList();
        for (int i = 0; i < coverage.scenes().size(); i++) {
            String scene = coverage.scenes().get(i);
            boolean caught = coverage.of(mistake).caughtBy(i);
            assertThat(lines).as("%s on %s: coverage says %s\n%s", mistake, scene, caught ? "caught" : "not caught",
                    run.transcript()).anyMatch(line -> line.startsWith(scene + ": " + (caught ? "FAIL" : "PASS")));
        }
    }
}
