package gfx.tick1.grade;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;

/**
 * The program {@code grade} runs in a JVM of its own to render with a student's code:
 * {@code StudentHarness CLASSES OUTPUT WIDTH HEIGHT SCENE...}. For each scene it loads the scene
 * with the starter code's {@code SceneLoader}, renders it with the student's {@code Renderer} and
 * writes {@code OUTPUT/<index>.png}, or {@code OUTPUT/<index>.error} with what went wrong.
 * {@code OUTPUT/progress} logs "start i" and "end i" lines, so that whoever stops this process
 * (on a time limit) or sees it die (System.exit, a crash) knows which scene it was on.
 *
 * <p>The student's classes are loaded by a class loader of their own whose parent is the
 * platform loader: they see the JDK and the starter code, not this program (whose own
 * {@code gfx.tick1.Tick1} would clash with the starter's).
 */
public final class StudentHarness {

    private StudentHarness() {
    }

    public static void main(String[] args) throws IOException {
        Path classes = Path.of(args[0]);
        Path output = Path.of(args[1]);
        int width = Integer.parseInt(args[2]);
        int height = Integer.parseInt(args[3]);
        Path progress = output.resolve(StudentProcess.PROGRESS_FILE);
        try (URLClassLoader student = new URLClassLoader(new URL[] {classes.toUri().toURL()},
                ClassLoader.getPlatformClassLoader())) {
            for (int i = 4; i < args.length; i++) {
                int index = i - 4;
                log(progress, "start " + index);
                try {
                    BufferedImage image = render(student, args[i], width, height);
                    ImageIO.write(image, "png", output.resolve(index + ".png").toFile());
                } catch (Throwable failure) { // the student's code may throw anything, errors included
                    Files.writeString(output.resolve(index + ".error"), describe(failure), StandardCharsets.UTF_8);
                }
                log(progress, "end " + index);
            }
        }
        // Student code may have left threads running; the results are written, so stop here.
        Runtime.getRuntime().halt(0);
    }

    private static BufferedImage render(ClassLoader student, String scenePath, int width, int height)
            throws ReflectiveOperationException {
        try {
            Class<?> loaderClass = student.loadClass("gfx.tick1.SceneLoader");
            Object loader = loaderClass.getConstructor(String.class).newInstance(scenePath);
            Object scene = loaderClass.getMethod("getScene").invoke(loader);
            Class<?> sceneClass = student.loadClass("gfx.tick1.Scene");
            Class<?> rendererClass = student.loadClass("gfx.tick1.Renderer");
            Object renderer = rendererClass.getConstructor(int.class, int.class).newInstance(width, height);
            Object image = rendererClass.getMethod("render", sceneClass).invoke(renderer, scene);
            if (!(image instanceof BufferedImage picture)) {
                throw new IllegalStateException("Renderer.render returned " + image + ", not an image");
            }
            if (picture.getWidth() != width || picture.getHeight() != height) {
                throw new IllegalStateException("Renderer.render returned a " + picture.getWidth() + " x "
                        + picture.getHeight() + " image, expected " + width + " x " + height);
            }
            return picture;
        } catch (InvocationTargetException e) {
            throw new StudentCodeException(e.getCause());
        }
    }

    /**
     * The exception, then its stack frames in the student's and the starter's code: the classes
     * of package gfx.tick1 itself, not of this harness in gfx.tick1.grade.
     */
    private static String describe(Throwable failure) {
        Throwable cause = failure instanceof StudentCodeException ? failure.getCause() : failure;
        List<String> lines = new ArrayList<>();
        lines.add(cause instanceof OutOfMemoryError ? cause + " (the memory limit was reached)" : cause.toString());
        for (StackTraceElement frame : cause.getStackTrace()) {
            if (frame.getClassName().matches("gfx\\.tick1\\.[^.]+") && lines.size() <= 8) {
                lines.add("at " + frame);
            }
        }
        return String.join("\n", lines);
    }

    private static void log(Path progress, String line) throws IOException {
        Files.writeString(progress, line + "\n", StandardCharsets.UTF_8, StandardOpenOption.CREATE,
                StandardOpenOption.APPEND);
    }

    /** An exception thrown by the student's (or the starter's) code, not by this harness. */
    private static final class StudentCodeException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        StudentCodeException(Throwable cause) {
            super(cause);
        }
    }
}
