package gfx.tick1.command.grade;

import gfx.tick1.command.shared.grader.intake.JavaDeclarations;
import gfx.tick1.command.shared.grader.intake.StudentFile;
import gfx.tick1.command.shared.grader.model.Submission;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * One student's two files as {@code grade --sphere --renderer} takes them: each read and checked as
 * UTF-8 (a file that is not, or is larger than any real one, is exit status 2), and recognised by
 * its class, as {@code tick1 diff} recognises them, so that two files given the wrong way round are
 * graded the right way round.
 */
final class StudentFiles {

    private StudentFiles() {
    }

    /**
     * The submission of the two files given, swapped (with a note on {@code err}) when the one given
     * as --sphere declares class Renderer and the one given as --renderer class Sphere.
     *
     * @throws IOException one line naming the file: not there, a folder, or not UTF-8
     */
    static Submission of(Path sphere, Path renderer, PrintWriter err) throws IOException {
        Submission.SourceFile sphereFile = read(sphere, "--sphere", "Sphere.java");
        Submission.SourceFile rendererFile = read(renderer, "--renderer", "Renderer.java");
        if (declaresClass(sphereFile, "Renderer") && declaresClass(rendererFile, "Sphere")) {
            err.println("tick1 grade: note: " + sphere + " declares class Renderer and " + renderer
                    + " class Sphere: graded the other way round");
            Submission.SourceFile swap = sphereFile;
            sphereFile = rendererFile;
            rendererFile = swap;
        }
        return new Submission("", "", "", sphereFile, rendererFile, null);
    }

    /**
     * The two files as they are, for {@code --format vpl}: a file that is not UTF-8 is the student's to
     * mend, so it is graded (and fails, saying so), not refused; it is then taken in the order given.
     *
     * @throws IOException one line naming the file: not there, or a folder
     */
    static Submission asSubmitted(Path sphere, Path renderer, PrintWriter err) throws IOException {
        try {
            return of(sphere, renderer, err);
        } catch (StudentFile.NotUtf8Exception e) {
            return new Submission("", "", "", new Submission.SourceFile(sphere.toString(),
                    StudentFile.readBytes(sphere)), new Submission.SourceFile(renderer.toString(),
                    StudentFile.readBytes(renderer)), null);
        }
    }

    private static Submission.SourceFile read(Path file, String option, String wanted) throws IOException {
        if (Files.isDirectory(file)) {
            throw new IOException(file + ": a folder, not a file: " + option + " wants the student's " + wanted);
        }
        byte[] content = StudentFile.readBytes(file);
        StudentFile.decode(file.toString(), content);
        return new Submission.SourceFile(file.toString(), content);
    }

    private static boolean declaresClass(Submission.SourceFile file, String name) throws IOException {
        return JavaDeclarations.firstClassOf(StudentFile.decode(file.path(), file.content())).equals(Optional.of(name));
    }
}
