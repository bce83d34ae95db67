package gfx.tick1.diff;

import gfx.tick1.cli.ExitStatus;
import gfx.tick1.diagnose.Variant;
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
import java.util.List;
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
 * member by member, with a hint where a change looks like a mistake of the diagnose catalogue.
 */
@Command(name = "diff",
        description = {"Shows where your Sphere.java and Renderer.java differ from ours in meaning.",
            "Compares your Sphere.java and Renderer.java with ours, ignoring comments, formatting, the package, "
                    + "imports and the order of fields and methods. Fields, constructors and methods are matched "
                    + "by signature; each one that differs is shown as a unified diff (- ours, + yours), with a "
                    + "one-line hint and the handout section to reread where the change looks like a common "
                    + "mistake. A file is recognised by its class. Colour on a terminal only."})
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
    public Integer call() {
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
                err.println("tick1 diff: " + parseError(file, e));
                return EXIT_CANNOT_COMPARE;
            } catch (IOException e) {
                err.println("tick1 diff: " + file + ": " + unreadable(file, e));
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
            List<String> removed = new ArrayList<>(), added = new ArrayList<>();
            for (List<LineDiff.Line> hunk : hunks) {
                lines.add(colours.cyan("@@ " + signature + note + " @@"));
                for (LineDiff.Line line : hunk) {
                    String text = line.kind() + line.text();
                    lines.add(line.kind() == '-' ? colours.red(text) : line.kind() == '+' ? colours.green(text) : text);
                    if (line.kind() == '-') {
                        removed.add(line.text().strip());
                    } else if (line.kind() == '+') {
                        added.add(line.text().strip());
                    }
                }
            }
            for (Variant hint : Hints.of(new Hints.Change(signature, removed, added, b))) {
                lines.add(colours.yellow("hint: this looks like \"" + hint.title() + "\": reread handout "
                        + hint.reread() + "."));
            }
        }
        return lines;
    }

    private static List<String> linesOf(String text) {
        return text == null ? List.of() : text.lines().toList();
    }

    /** Our Sphere.java or Renderer.java, as the build copies their source into the program. */
    static JavaMembers ours(String className) {
        String name = className + ".java";
        try (InputStream in = DiffCommand.class.getResourceAsStream("/gfx/tick1/diff/reference/" + name)) {
            if (in == null) {
                throw new IllegalStateException("the program is missing our " + name + " (a broken build)");
            }
            return JavaMembers.parse(name, new String(in.readAllBytes(), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (JavaMembers.ParseException e) {
            throw new IllegalStateException("our own " + name + " does not parse: " + e.getMessage(), e);
        }
    }

    private static String read(Path file) throws IOException {
        return Files.readString(file, StandardCharsets.UTF_8);
    }

    /**
     * Why a file cannot be read, with the files meant where they can be seen: those of a folder
     * given, or the file of that name in the starter kit's src/gfx/tick1/.
     */
    private static String unreadable(Path file, IOException e) {
        if (Files.isDirectory(file)) {
            List<String> inside = StarterKit.STUDENT_CLASSES.stream().map(name -> file.resolve(name + ".java"))
                    .filter(Files::isRegularFile).map(Path::toString).toList();
            return "a folder, not a file" + (inside.isEmpty() ? "; give your Sphere.java and Renderer.java"
                    : "; did you mean tick1 diff " + String.join(" ", inside) + "?");
        }
        Path name = file.getFileName();
        Path inTheKit = name == null ? null : Path.of(StarterKit.SOURCE_FOLDER).resolve(name);
        boolean there = inTheKit != null && !Files.exists(file) && Files.isRegularFile(inTheKit);
        return IoErrors.reason(e) + (there ? "; did you mean " + inTheKit + "?" : "");
    }

    /** A parse error in one line: JavaParser's list of the tokens it expected says nothing to a student. */
    private static String parseError(Path file, JavaMembers.ParseException e) {
        if (!file.toString().toLowerCase(java.util.Locale.ROOT).endsWith(".java")) {
            return file + ": not Java source; give your Sphere.java and Renderer.java";
        }
        return e.getMessage().replaceFirst(", expected one of .*$", "");
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
