package gfx.tick1.command.shared.grader.harness;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.StringWriter;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.FileObject;
import javax.tools.ForwardingJavaFileManager;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileManager;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.StandardLocation;
import javax.tools.ToolProvider;

/**
 * Compiles a student's {@code Sphere.java} and {@code Renderer.java} with the starter kit's other
 * classes, in memory, through the JDK's own compiler (javax.tools): no files but the student's are
 * read and nothing is written. Errors carry the student's own file names and line numbers.
 * {@code grade} runs it inside the sandbox, where it must not need anything but the JDK: the
 * starter kit's classes are handed to it as sources.
 */
public final class StudentCompiler {

    /** What compiling gave: the class files by binary name, or the errors (never both). */
    public record Result(Map<String, byte[]> classes, List<String> errors) {

        public boolean compiled() {
            return errors.isEmpty();
        }

        /** Writes the class files under {@code folder} in the usual package folders. */
        public void writeClasses(Path folder) throws IOException {
            for (Map.Entry<String, byte[]> entry : classes.entrySet()) {
                Path file = folder.resolve(entry.getKey().replace('.', '/') + ".class");
                Files.createDirectories(file.getParent());
                Files.write(file, entry.getValue());
            }
        }
    }

    /** The one error when the compiler itself ran out of memory (a source can make it need any amount). */
    public static final String OUT_OF_MEMORY = "the compiler ran out of memory";

    /** No JDK compiler here (a JRE, or a stripped runtime). */
    public static final class NoCompilerException extends Exception {
        private static final long serialVersionUID = 1L;

        NoCompilerException() {
            super("grading needs a JDK: this Java (" + System.getProperty("java.home") + ") has no compiler");
        }
    }

    /**
     * Compiles the given sources of package gfx.tick1 with nothing on the class path. This method
     * needs only the JDK: {@code grade} runs it inside the sandbox, through {@link StudentHarness}.
     */
    public Result compile(List<Source> sources) throws IOException, NoCompilerException {
        JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
        if (compiler == null) {
            throw new NoCompilerException();
        }
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        Map<String, byte[]> classes = new TreeMap<>();
        StandardJavaFileManager standard =
                compiler.getStandardFileManager(diagnostics, Locale.ROOT, StandardCharsets.UTF_8);
        // Nothing on the class path: the student's code sees the JDK and the starter code only,
        // never this program's own classes (which include a gfx.tick1.Tick1 of their own).
        standard.setLocation(StandardLocation.CLASS_PATH, List.of());
        try (JavaFileManager files = new InMemoryOutput(standard, classes)) {
            List<String> options = List.of("-proc:none", "-Xlint:none", "-nowarn", "-g");
            // What javac prints outside diagnostics: a crash, such as running out of memory.
            StringWriter said = new StringWriter();
            Boolean ok = compiler.getTask(said, files, diagnostics, options, null, sources).call();
            List<String> errors = new ArrayList<>();
            for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
                if (d.getKind() == Diagnostic.Kind.ERROR) {
                    errors.add(describe(d));
                }
            }
            if (!ok && errors.isEmpty()) {
                errors.add(said.toString().contains("OutOfMemoryError") ? OUT_OF_MEMORY
                        : "the compiler failed without saying why");
            }
            return errors.isEmpty() ? new Result(classes, List.of()) : new Result(Map.of(), errors);
        }
    }

    /** "Sphere.java:42:13: error: ';' expected", then the source line and a caret under the column. */
    private static String describe(Diagnostic<? extends JavaFileObject> d) {
        StringBuilder text = new StringBuilder();
        if (d.getSource() != null) {
            text.append(d.getSource().getName());
            if (d.getLineNumber() != Diagnostic.NOPOS) {
                text.append(':').append(d.getLineNumber()).append(':').append(d.getColumnNumber());
            }
            text.append(": ");
        }
        text.append("error: ").append(d.getMessage(Locale.ROOT));
        if (d.getSource() instanceof Source source && d.getLineNumber() != Diagnostic.NOPOS) {
            String line = source.line((int) d.getLineNumber());
            if (line != null) {
                text.append('\n').append("    ").append(line.stripTrailing());
                int column = (int) Math.max(1, d.getColumnNumber());
                text.append('\n').append("    ").append(" ".repeat(Math.min(column - 1, line.length()))).append('^');
            }
        }
        return text.toString();
    }

    /** A source held in memory under the name to report it by. */
    public static final class Source extends SimpleJavaFileObject {
        private final String className;
        private final String displayName;
        private final String code;

        /** The source of public class {@code className} of gfx.tick1, reported as {@code displayName}. */
        public Source(String className, String displayName, String code) {
            super(URI.create("memory:///gfx/tick1/" + className + ".java"), Kind.SOURCE);
            this.className = className;
            this.displayName = displayName;
            this.code = code;
        }

        @Override
        public String getName() {
            return displayName;
        }

        @Override
        public boolean isNameCompatible(String simpleName, Kind kind) {
            // The public class Sphere may live in a file the student called anything.
            return kind == Kind.SOURCE && simpleName.equals(className);
        }

        @Override
        public CharSequence getCharContent(boolean ignoreEncodingErrors) {
            return code;
        }

        String line(int number) {
            String[] lines = code.split("\r\n|\r|\n", -1);
            return number >= 1 && number <= lines.length ? lines[number - 1].replace('\t', ' ') : null;
        }
    }

    /** Collects the class files the compiler writes, instead of writing them to disk. */
    private static final class InMemoryOutput extends ForwardingJavaFileManager<StandardJavaFileManager> {
        private final Map<String, byte[]> classes;

        InMemoryOutput(StandardJavaFileManager files, Map<String, byte[]> classes) {
            super(files);
            this.classes = classes;
        }

        @Override
        public JavaFileObject getJavaFileForOutput(Location location, String className, JavaFileObject.Kind kind,
                FileObject sibling) {
            return new SimpleJavaFileObject(URI.create("memory:///" + className.replace('.', '/') + ".class"), kind) {
                @Override
                public OutputStream openOutputStream() {
                    return new ByteArrayOutputStream() {
                        @Override
                        public void close() {
                            classes.put(className, toByteArray());
                        }
                    };
                }
            };
        }
    }
}
