package gfx.tick1.command.shared.grader.cohort;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.grading.ReferenceChoice;
import gfx.tick1.command.shared.grader.model.Submission;
import gfx.tick1.command.shared.grader.sandbox.Enforcement;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A stored result is reused only by a grade that would give it again: the same files, scenes and
 * limits, and a sandbox that holds the code to the same rules. A result graded without the sandbox,
 * or without the kernel's hold on each run's disk, is graded again under them, and the other way round.
 */
class ResultStoreKeyTest {

    private static final Submission SUBMISSION = new Submission("Bo_8_assignsubmission_file", "8", "Bo",
            new Submission.SourceFile("Sphere.java", "class Sphere {}".getBytes(StandardCharsets.UTF_8)),
            new Submission.SourceFile("Renderer.java", "class Renderer {}".getBytes(StandardCharsets.UTF_8)), null);

    /** Everything a sandbox can hold the code to, as a root grader on a machine that allows it all. */
    private static final Enforcement EVERYTHING = new Enforcement(true, true, true, true, true);
    /** {@code --no-sandbox}. */
    private static final Enforcement NO_SANDBOX = new Enforcement(false, false, false, false, false);

    @TempDir
    Path work;

    private Grading grading;

    @BeforeEach
    void prepareGrading() throws IOException {
        grading = Grading.prepare(work, null,
                new Grading.Limits(16, 12, Duration.ofSeconds(10), 256, ReferenceChoice.either));
    }

    @Test
    void theSameFilesGradedUnderTheSameRulesFindTheirStoredResult() throws IOException {
        assertThat(ResultStore.key(SUBMISSION, grading, EVERYTHING)).as("the key under the same rules")
                .isEqualTo(ResultStore.key(SUBMISSION, grading, new Enforcement(true, true, true, true, true)));
    }

    @Test
    void aResultGradedWithoutTheSandboxIsNotReusedByASandboxedGrade() throws IOException {
        assertThat(ResultStore.key(SUBMISSION, grading, NO_SANDBOX)).as("the key of a --no-sandbox result")
                .isNotEqualTo(ResultStore.key(SUBMISSION, grading, EVERYTHING));
    }

    @Test
    void aResultGradedWithoutTheKernelsHoldOnTheOutputFolderIsNotReusedByAGradeWithIt() throws IOException {
        assertThat(ResultStore.key(SUBMISSION, grading, new Enforcement(true, true, true, true, false)))
                .as("the key of a result whose output folder was on the host's disk")
                .isNotEqualTo(ResultStore.key(SUBMISSION, grading, EVERYTHING));
    }

    @Test
    void aResultGradedWithoutControlGroupsIsNotReusedByAGradeWithThem() throws IOException {
        assertThat(ResultStore.key(SUBMISSION, grading, new Enforcement(true, true, false, true, true)))
                .as("the key of a result whose runs were limited per process only")
                .isNotEqualTo(ResultStore.key(SUBMISSION, grading, EVERYTHING));
    }

    @Test
    void aResultGradedAsANormalUserIsNotReusedByAGradeAsRoot() throws IOException {
        assertThat(ResultStore.key(SUBMISSION, grading, new Enforcement(true, false, true, true, false)))
                .as("the key of a result graded under the grader's own user")
                .isNotEqualTo(ResultStore.key(SUBMISSION, grading, new Enforcement(true, true, true, true, false)));
    }

    @Test
    void aResultGradedWithoutTheSeccompFilterIsNotReusedByAGradeWithIt() throws IOException {
        assertThat(ResultStore.key(SUBMISSION, grading, new Enforcement(true, true, true, false, true)))
                .as("the key of a result whose runs could reserve disk space unseen")
                .isNotEqualTo(ResultStore.key(SUBMISSION, grading, EVERYTHING));
    }

    @Test
    void aResultGradedByAnotherBuildOfTheSameVersionIsNotReused(@TempDir Path builds) throws IOException {
        Path oneBuild = Files.createDirectories(builds.resolve("one").resolve("gfx"));
        Path otherBuild = Files.createDirectories(builds.resolve("other").resolve("gfx"));
        Files.write(oneBuild.resolve("Grader.class"), new byte[] {(byte) 0xca, (byte) 0xfe, 1});
        Files.write(otherBuild.resolve("Grader.class"), new byte[] {(byte) 0xca, (byte) 0xfe, 2});

        assertThat(ResultStore.key(SUBMISSION, grading, EVERYTHING, ResultStore.build(oneBuild.getParent())))
                .as("the key of a result graded by another build of tick1's code, of the same version")
                .isNotEqualTo(ResultStore.key(SUBMISSION, grading, EVERYTHING, ResultStore.build(otherBuild
                        .getParent())));
    }
}
