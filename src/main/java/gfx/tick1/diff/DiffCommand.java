package gfx.tick1.diff;

import gfx.tick1.cli.ExitStatus;
import gfx.tick1.io.IoErrors;
import gfx.tick1.starter.StarterKit;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code tick1 diff}: a student's Sphere.java and Renderer.java against ours, by meaning. Both
 * sides are parsed; comments, layout, the package, imports and the order of members are set
 * aside, members are matched by signature, and what still differs is shown as a unified diff,
 * member by member. The hints after it come only from probes of the student's own methods, run
 * in the sandbox as {@code grade} runs them ({@link Hints}).
 */
@Command(name = "diff",
        description = {
            "Compares your Sphere.java and Renderer.java with ours, ignoring comments, formatting, the package, "
                    + "imports and the order of fields and methods. Fields, constructors and methods are matched "
                    + "by signature; each one that differs is shown as a unified diff (- ours, + yours). When "
                    + "something differs and the files compile, your intersectionWith and illuminate are run in the "
                    + "sandbox on fixed inputs, and each property they get wrong is a hint with the handout section "
                    + "to reread; without the sandbox there are no hints, and a line says why. A file is recognised "
                    + "by its class. Colour on a terminal only."})
public final class DiffCommand implements Callable<Integer> {

    @ExitStatus("nothing differs in meaning (and nothing is printed)")
    public static final int EXIT_SAME = 0;
    @ExitStatus("something differs")
    public static final int EXIT_DIFFERENT = 1;
    @ExitStatus("a file cannot be read or parsed, or is not a Sphere or Renderer class")
    public static final int EXIT_CANNOT_COMPARE = 2;

    /** The classes a student writes, whose reference source the program carries. */

    @Spec
    private CommandSpec spec;

    @Parameters(arity = "1..2", paramLabel = "FILE.java", description = "Your Sphere.java and/or Renderer.java.")
    private List<Path> files;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        List<JavaMembers> theirs = new ArrayList<>();
        Set<String> classes = new LinkedHashSet<>();
        for (Path file : files) {
            try {
                JavaMembers parsed = JavaMembers.parse(file.toString(), read(file));
                if (!StarterKit.STUDENT_CLASSES.contains(parsed.className())) {
                    err.println("tick1 diff: " + file + ": class " + parsed.className()
                            + ": expected Sphere or Renderer, the two classes of the tick");
                    return EXIT_CANNOT_COMPARE;
                }
                if (!classes.add(parsed.className())) {
                    err.println("tick1 diff: " + file + ": a second " + parsed.className()
                            + " class: give one Sphere.java and one Renderer.java");
                    return EXIT_CANNOT_COMPARE;
                }
                theirs.add(parsed);
            } catch (JavaMembers.ParseException e) {
                err.println("tick1 diff: " + e.getMessage());
                return EXIT_CANNOT_COMPARE;
            } catch (IOException e) {
                err.println("tick1 diff: " + file + ": " + IoErrors.reason(e));
                return EXIT_CANNOT_COMPARE;
            }
        }
        Colours colours = new Colours(CommandLine.Help.Ansi.AUTO.enabled());
        boolean differs = false;
        for (int i = 0; i < theirs.size(); i++) {
            List<String> report = compare(ours(theirs.get(i).className()), theirs.get(i), files.get(i), colours);
            report.forEach(out::println);
            differs |= !report.isEmpty();
        }
        if (differs) {
            hints(theirs, out, colours);
        }
        return differs ? EXIT_DIFFERENT : EXIT_SAME;
    }

    /** The unified diff of one file, member by member in our order, then members only theirs has. */
    static List<String> compare(JavaMembers ours, JavaMembers theirs, Path file, Colours colours) {
        Set<String> signatures = new LinkedHashSet<>(ours.members().keySet());
        signatures.addAll(theirs.members().keySet());
        List<String> lines = new ArrayList<>();
        for (String signature : signatures) {
            List<String> a = linesOf(ours.members().get(signature));
            List<String> b = linesOf(theirs.members().get(signature));
            List<List<LineDiff.Line>> hunks = LineDiff.hunks(a, b);
            if (hunks.isEmpty()) {
                continue;
            }
            if (lines.isEmpty()) {
                lines.add(colours.bold("--- ours: " + ours.className() + ".java"));
                lines.add(colours.bold("+++ yours: " + file));
            }
            String note = a.isEmpty() ? " (only in yours)" : b.isEmpty() ? " (missing from yours)" : "";
            for (List<LineDiff.Line> hunk : hunks) {
                lines.add(colours.cyan("@@ " + signature + note + " @@"));
                for (LineDiff.Line line : hunk) {
                    String text = line.kind() + line.text();
                    lines.add(line.kind() == '-' ? colours.red(text) : line.kind() == '+' ? colours.green(text) : text);
                }
            }
        }
        return lines;
    }

    /** The hints of the probes of their methods, or the one line that says why there are none. */
    private void hints(List<JavaMembers> theirs, PrintWriter out, Colours colours) throws InterruptedException {
        Map<String, String> given = new LinkedHashMap<>(), reference = new LinkedHashMap<>();
        for (int i = 0; i < theirs.size(); i++) {
            try {
                given.put(theirs.get(i).className(), read(files.get(i)));
            } catch (IOException e) {
                out.println(colours.yellow("no hints: " + files.get(i) + ": " + IoErrors.reason(e)));
                return;
            }
        }
        for (String className : StarterKit.STUDENT_CLASSES) {
            reference.put(className, ourSource(className));
        }
        Hints.of(given, reference).forEach(line -> out.println(colours.yellow(line)));
    }

    private static List<String> linesOf(String text) {
        return text == null ? List.of() : text.lines().toList();
    }

    /** The source of our Sphere.java or Renderer.java, as the build copies it into the program. */
    private static String ourSource(String className) {
        String name = className + ".java";
        try (InputStream in = DiffCommand.class.getResourceAsStream("/gfx/tick1/diff/reference/" + name)) {
            if (in == null) {
                throw new IllegalStateException("the program is missing our " + name + " (a broken build)");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Our Sphere.java or Renderer.java, parsed. */
    static JavaMembers ours(String className) {
        String name = className + ".java";
        try {
            return JavaMembers.parse(name, ourSource(className));
        } catch (JavaMembers.ParseException e) {
            throw new IllegalStateException("our own " + name + " does not parse: " + e.getMessage(), e);
        }
    }

    private static String read(Path file) throws IOException {
        return Files.readString(file, StandardCharsets.UTF_8);
    }


    /** ANSI colours for a terminal, or the text as it is. */
    record Colours(boolean on) {
        String red(String text) {
            return paint("31", text);
        }

        String green(String text) {
            return paint("32", text);
        }

        String yellow(String text) {
            return paint("33", text);
        }

        String cyan(String text) {
            return paint("36", text);
        }

        String bold(String text) {
            return paint("1", text);
        }

        private String paint(String code, String text) {
            return on ? "\u001B[" + code + "m" + text + "\u001B[0m" : text;
        }
    }
}
