package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.Tick1;
import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import java.io.BufferedWriter;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The closing lines of a cohort's grade reach the standard output when it is a pipe or a file
 * (buffered, as Java's is then), not only when the test's own writer passes them straight on.
 */
@ExtendWith(SandboxNeeded.class)
class GradeCohortStdoutTest {

    @TempDir
    Path dir;

    @Test
    void theClosingLinesAreWrittenOutBeforeTheGradeEnds() throws IOException {
        Path student = Files.createDirectories(dir.resolve("download")
                .resolve("Ada Lovelace_1001_assignsubmission_file"));
        Files.writeString(student.resolve("Sphere.java"), "class Sphere {}");
        Files.writeString(student.resolve("Renderer.java"), "class Renderer {}");
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new RenderCommand(new ByteArrayOutputStream()));
        commandLine.setOut(new PrintWriter(new BufferedWriter(out), true));
        commandLine.setErr(new PrintWriter(err, true));

        commandLine.execute("grade", "--submissions", student.getParent().toString(), "--report",
                dir.resolve("report").toString());

        assertThat(out.toString()).as("the standard output, unflushed by the test; stderr: " + err)
                .contains("Graded 1 submission");
    }
}
