package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.diff.DiffCommand;
import gfx.tick1.command.grade.GradeCommand;
import gfx.tick1.command.grade.StudentSolution;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A temporary folder (Java's java.io.tmpdir) that cannot hold tick1's work: the commands that work in it say in
 * one line which folder and why, and how to give another, never "internal error".
 */
class UnusableTemporaryFolderTest {

    @TempDir
    Path dir;

    @Test
    void aGradeWithoutTheSandboxNamesAMissingTemporaryFolder() throws Exception {
        Path missing = dir.resolve("missing");

        CliRun run = grade(missing, "--no-sandbox");

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err().lines()).as(run.transcript()).contains("tick1 grade: the temporary folder " + missing
                + " (java.io.tmpdir) cannot be used: no such folder; give tick1 a folder it can write with "
                + "JAVA_OPTS=-Djava.io.tmpdir=FOLDER").noneMatch(line -> line.contains("internal error"));
    }

    @Test
    void aGradeInTheSandboxBlamesTheTemporaryFolderNotTheSandbox() throws Exception {
        Path file = Files.writeString(dir.resolve("a-file"), "");

        CliRun run = grade(file);

        assertThat(run.status()).as(run.transcript()).isEqualTo(GradeCommand.EXIT_USAGE);
        assertThat(run.err()).as(run.transcript()).isEqualTo("tick1 grade: the temporary folder " + file
                + " (java.io.tmpdir) cannot be used: not a folder; give tick1 a folder it can write with "
                + "JAVA_OPTS=-Djava.io.tmpdir=FOLDER\n");
    }

    @Test
    void aDiffSaysWhyBehaviourCouldNotBeCheckedInOneLine() throws Exception {
        Path missing = dir.resolve("missing");
        Path[] files = write(StudentSolution.correct().editSphere("double s = s1 > 0 ? s1 : s2;", "double s = s2;"));

        CliRun run = CliRun.inJvm(dir, List.of("-Djava.io.tmpdir=" + missing), "diff", "--no-sandbox",
                files[0].toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
        assertThat(run.out().lines()).as(run.transcript()).contains("behaviour could not be checked: the temporary "
                + "folder " + missing + " (java.io.tmpdir) cannot be used: no such folder; give tick1 a folder it "
                + "can write with JAVA_OPTS=-Djava.io.tmpdir=FOLDER");
    }

    private CliRun grade(Path temporary, String... more) throws Exception {
        Path[] files = write(StudentSolution.correct());
        List<String> args = new ArrayList<>(List.of("grade", "--sphere", files[0].toString(),
                "--renderer", files[1].toString(), "--width", "16", "--height", "12"));
        args.addAll(List.of(more));
        return CliRun.inJvm(dir, List.of("-Djava.io.tmpdir=" + temporary), args.toArray(String[]::new));
    }

    private Path[] write(StudentSolution solution) throws IOException {
        Path folder = Files.createDirectories(dir.resolve("student"));
        return new Path[] {Files.writeString(folder.resolve("Sphere.java"), solution.sphere()),
            Files.writeString(folder.resolve("Renderer.java"), solution.renderer())};
    }
}
