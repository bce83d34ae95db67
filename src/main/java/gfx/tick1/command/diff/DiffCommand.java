package gfx.tick1.command.diff;

import gfx.tick1.command.shared.behaviour.BehaviourCheck;
import gfx.tick1.command.shared.behaviour.DrawnScenes;
import gfx.tick1.command.shared.behaviour.RunIn;
import gfx.tick1.command.shared.behaviour.SandboxAhead;
import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.command.shared.cli.TemporaryFolder;
import gfx.tick1.command.shared.grader.intake.StudentFile;
import gfx.tick1.command.shared.javacode.JavaMembers;
import gfx.tick1.command.shared.javacode.Nesting;
import gfx.tick1.command.shared.javacode.ReferenceMembers;
import gfx.tick1.command.shared.javacode.SameMeaning;
import gfx.tick1.command.shared.kit.StarterKit;
import gfx.tick1.engine.io.IoErrors;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine;

/**
 * {@code tick1 diff}: a student's Sphere.java and Renderer.java against ours, by meaning. Both
 * sides are parsed; comments, layout, the package, imports and the order of members are set
 * aside, members are matched by signature, a member that means the same as ours (or, where the
 * starter code gives it whole, as the starter's) is left out ({@link SameMeaning}), and what still
 * differs is shown as a unified diff, member by member. Before it, one line a method says how the
 * student's own methods behaved, run in the sandbox as {@code grade} runs them ({@link Hints}).
 */
@Command(name = "diff",
        description = {"Shows where your Sphere.java and Renderer.java differ from ours in meaning.",
            "Compares your Sphere.java and Renderer.java with ours, ignoring comments, formatting, the package, "
                    + "imports, the order of fields and methods, the names of locals and parameters, final and "
                    + "annotations on them, this. on a "
                    + "field, parentheses that do not change the expression, and the order of declarations that "
                    + "do not depend on each other. Fields, constructors and methods are matched by signature; each "
                    + "one that still differs from ours (and, for what the starter code gives whole, from the "
                    + "starter's) is shown as a unified diff (- ours, + yours). When something differs and the "
                    + "files compile, your intersectionWith and illuminate are first run in the sandbox on the inputs "
                    + "grade uses, and one line each says that it behaves as ours or where it does not; exit 0 when "
                    + "they behave as ours and nothing else differs, or, given both files, what else differs leaves "
                    + "tick1.xml and basic_scene.xml drawn as ours, pixel for pixel. Without the sandbox a line says "
                    + "behaviour could not be checked, unless --no-sandbox runs your methods without it. A file is "
                    + "recognised by its class. Colour on a terminal only (not with NO_COLOR set, nor TERM=dumb)."})
public final class DiffCommand implements Callable<Integer> {

    @ExitStatus("only methods that behave as ours differ, or members that leave the handout's scenes drawn as ours")
    public static final int EXIT_SAME = 0;
    @ExitStatus("a method does not behave as ours (even on an untested edge), another "
            + "member differs and the scenes were not drawn as ours, or "
            + "behaviour was not checked")
    public static final int EXIT_DIFFERENT = 1;
    @ExitStatus("a file cannot be read or parsed, or is not a Sphere or Renderer class")
    public static final int EXIT_CANNOT_COMPARE = 2;

    /** The classes a student writes, whose reference source the program carries. */

    @Spec
    private CommandSpec spec;

    @Parameters(arity = "1..2", paramLabel = "FILE.java", description = "Your Sphere.java and/or Renderer.java.")
    private List<Path> files;

    @Option(names = "--no-sandbox",
            description = "The code is yours: run your methods without the sandbox, where bubblewrap is missing or "
                    + "cannot run (macOS, Windows), in a Java process limited only in time and heap, with your "
                    + "permissions.")
    private boolean noSandbox;

    /**
     * The stack of the thread that parses and compares: both recurse through the syntax tree, so
     * code nested a few hundred deep (1 + 1 + ..., or ((...))) would overflow an ordinary thread's.
     */
    private static final long DEEP_STACK = 256L << 20;

    @Override
    public Integer call() throws InterruptedException {
        FutureTask<Integer> task = new FutureTask<>(this::compareFiles);
        Thread worker = new Thread(null, task, "tick1 diff", DEEP_STACK);
        worker.start();
        try {
            return task.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof RuntimeException unchecked) {
                throw unchecked;
            }
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw new IllegalStateException(e.getCause());
        }
    }

    private int compareFiles() {
        // Made while the files are parsed: most diffs run the methods, and making it waits on processes.
        SandboxAhead sandbox = SandboxAhead.start(noSandbox ? RunIn.OWN_PROCESS : RunIn.SANDBOX);
        PrintWriter out = spec.commandLine().getOut();
        List<JavaMembers> theirs = new ArrayList<>();
        Set<String> classes = new LinkedHashSet<>();
        // Ours, parsed once a class: each of their files is parsed like it, then compared with it.
        Map<String, JavaMembers> oursOf = new HashMap<>();
        for (Path file : files) {
            try {
                JavaMembers parsed = JavaMembers.parse(file.toString(), read(file),
                        className -> StarterKit.STUDENT_CLASSES.contains(className)
                                ? oursOf.computeIfAbsent(className, ReferenceMembers::ours) : null);
                if (!StarterKit.STUDENT_CLASSES.contains(parsed.className())) {
                    throw new CommandFailure(EXIT_CANNOT_COMPARE, file + ": class " + parsed.className()
                            + ": expected Sphere or Renderer, the two classes of the tick");
                }
                if (!classes.add(parsed.className())) {
                    throw new CommandFailure(EXIT_CANNOT_COMPARE, file + ": a second " + parsed.className()
                            + " class: give one Sphere.java and one Renderer.java");
                }
                if (!parsed.tooDeep().isEmpty()) {
                    throw new CommandFailure(EXIT_CANNOT_COMPARE, parsed.tooDeep().get(0).message());
                }
                theirs.add(parsed);
            } catch (JavaMembers.ParseException e) {
                throw new CommandFailure(EXIT_CANNOT_COMPARE, parseError(file, e));
            } catch (StudentFile.NotUtf8Exception | StudentFile.TooLargeException e) {
                // Their message names the file, and where in it the first byte that is not UTF-8 is.
                throw new CommandFailure(EXIT_CANNOT_COMPARE, e.getMessage());
            } catch (IOException e) {
                throw new CommandFailure(EXIT_CANNOT_COMPARE, file + ": " + unreadable(file, e));
            } catch (StackOverflowError e) {
                throw new CommandFailure(EXIT_CANNOT_COMPARE, file + ": blocks, statements or expressions nested "
                        + "too deeply to parse; code nested more than " + Nesting.MOST_DEPTH + " deep is not compared");
            }
        }
        Colours colours = new Colours(Colours.wanted(System.console() != null, System.getenv(),
                CommandLine.Help.Ansi.AUTO.enabled()));
        List<String> report = new ArrayList<>();
        boolean onlyMethodsDiffer = true;
        for (int i = 0; i < theirs.size(); i++) {
            String className = theirs.get(i).className();
            JavaMembers ours = oursOf.computeIfAbsent(className, ReferenceMembers::ours);
            JavaMembers starter = ReferenceMembers.starter(className, ours);
            report.addAll(compare(ours, starter, theirs.get(i), files.get(i), colours));
            onlyMethodsDiffer &= BEHAVIOUR_COVERS.containsAll(differingMembers(ours, starter, theirs.get(i)).keySet()
                    .stream().filter(signature -> ours.members().containsKey(signature)).toList());
        }
        if (report.isEmpty()) {
            return EXIT_SAME;
        }
        // Another member of ours that differs (render, trace, a constructor) is shown to change no image when the
        // code, with its methods behaving as ours, draws the handout's scenes as ours does; with one file given, the
        // other is the kit's, which draws no image of ours.
        boolean draw = !onlyMethodsDiffer && classes.containsAll(StarterKit.STUDENT_CLASSES);
        Hints.Said said = hints(theirs, sandbox, out, colours, draw);
        boolean behaves = said != null && said.behavesAsOurs();
        DrawnScenes drawn = behaves ? said.drawn() : null;
        // Methods that behave as ours are no difference, however written; nor is any other edit that leaves the
        // images drawn as ours.
        boolean same = behaves && (onlyMethodsDiffer || drawn != null && drawn.asOurs());
        if (said != null) {
            if (same) {
                out.println(colours.green(onlyMethodsDiffer ? NOTHING_TO_FIX : NOTHING_TO_FIX_DRAWN));
            }
            said.first().forEach(line -> out.println(colours.yellow(line)));
        }
        if (drawn != null) {
            drawn.differences().forEach(line -> out.println(colours.yellow(line)));
        }
        if (same) {
            out.println(colours.bold(onlyMethodsDiffer ? FORM_ONLY : DRAWN_THE_SAME));
        }
        report.forEach(out::println);
        if (said != null) {
            said.after().forEach(line -> out.println(colours.yellow(line)));
        }
        return same ? EXIT_SAME : EXIT_DIFFERENT;
    }

    /** The first line where the methods behave as ours and nothing else of ours differs in meaning. */
    static final String NOTHING_TO_FIX = "Nothing to fix: your intersectionWith and illuminate behave as ours, "
            + "and nothing else of ours differs in meaning.";
    /** The heading of the hunks of such code. */
    static final String FORM_ONLY = "Differences of form, which do not change what your code does:";
    /**
     * The first line where the methods behave as ours and other members of ours differ too, but the
     * student's code drew the handout's scenes as ours does.
     */
    static final String NOTHING_TO_FIX_DRAWN = "Nothing to fix: your intersectionWith and illuminate behave as "
            + "ours, and your code draws " + String.join(" and ", DrawnScenes.SCENES)
            + " as ours does, pixel for pixel.";
    /** The heading of the hunks of such code. */
    static final String DRAWN_THE_SAME = "Differences that change neither what your methods return nor these images:";

    /**
     * The members whose meaning the behaviour comparison checks: the two methods it calls, and
     * getNormalAt, whose answer is intersectionWith's normal. Members only in theirs are helpers of these or unused.
     */
    private static final Set<String> BEHAVIOUR_COVERS = Set.of("intersectionWith(Ray)", "getNormalAt(Vector3)",
            "illuminate(Scene, Sphere, Vector3, Vector3)");

    /**
     * What their methods did, for the lines before the diff (or why it could not be checked), and with
     * {@code draw} how the code drew the handout's scenes, run in {@code sandbox}; null, with a line printed,
     * when the files could not be given to the sandbox.
     */
    private Hints.Said hints(List<JavaMembers> theirs, SandboxAhead sandbox, PrintWriter out, Colours colours,
            boolean draw) {
        Map<String, String> given = new LinkedHashMap<>(), starter = new LinkedHashMap<>();
        for (int i = 0; i < theirs.size(); i++) {
            try {
                given.put(theirs.get(i).className(), read(files.get(i)));
            } catch (IOException e) {
                out.println(colours.yellow("behaviour could not be checked: " + files.get(i) + ": "
                        + IoErrors.reason(e)));
                return null;
            }
        }
        // A file not given is the starter kit's: its method is not reported.
        for (String className : StarterKit.STUDENT_CLASSES) {
            starter.put(className, StarterKit.source(className));
        }
        Optional<String> temporary = TemporaryFolder.problem();
        if (temporary.isPresent()) {
            out.println(colours.yellow("behaviour could not be checked: " + temporary.get()));
            return null;
        }
        try {
            Hints.Said said = Hints.of(given, starter, sandbox, draw);
            if (noSandbox && said.ran()) {
                PrintWriter err = spec.commandLine().getErr();
                err.println("tick1 diff: note: --no-sandbox: your methods ran without a sandbox, in "
                        + BehaviourCheck.LIMITS);
                err.flush();
            }
            return said;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            out.println(colours.yellow("behaviour could not be checked: stopped before your methods had run"));
            return null;
        }
    }

    /**
     * The unified diff of one file, member by member in our order, then members only theirs has.
     * A member is left out when it means the same as ours or, for a member the starter code
     * gives whole (one without a TODO), as the starter's ({@code starter} may be null).
     */
    static List<String> compare(JavaMembers ours, JavaMembers starter, JavaMembers theirs, Path file,
            Colours colours) {
        List<String> lines = new ArrayList<>();
        differingMembers(ours, starter, theirs).forEach((signature, hunks) -> {
            if (lines.isEmpty()) {
                lines.add(colours.bold("--- ours: " + ours.className() + ".java"));
                lines.add(colours.bold("+++ yours: " + file));
            }
            boolean mine = ours.members().containsKey(signature), yours = theirs.members().containsKey(signature);
            lines.addAll(member(signature, !mine ? " (only in yours)" : !yours ? " (missing from yours)" : "", hunks,
                    colours));
        });
        return lines;
    }

    /** The members that differ in meaning, by signature, with their hunks: in our order, then those only theirs has. */
    static Map<String, List<List<LineDiff.Line>>> differingMembers(JavaMembers ours, JavaMembers starter,
            JavaMembers theirs) {
        Set<String> signatures = new LinkedHashSet<>(ours.members().keySet());
        signatures.addAll(theirs.members().keySet());
        Map<String, List<List<LineDiff.Line>>> differing = new LinkedHashMap<>();
        for (String signature : signatures) {
            JavaMembers.Member our = ours.members().get(signature);
            JavaMembers.Member their = theirs.members().get(signature);
            JavaMembers.Member given = starter == null ? null : starter.members().get(signature);
            if (our != null && their != null && (our.key().equals(their.key())
                    || given != null && !given.todo() && given.key().equals(their.key()))) {
                continue;
            }
            List<String> a = our == null ? List.of() : our.lines();
            List<String> b = their == null ? List.of() : their.lines();
            List<List<LineDiff.Line>> hunks = LineDiff.hunks(a, our == null ? a : our.keyLines(), b,
                    their == null ? b : their.keyLines());
            if (!hunks.isEmpty()) {
                differing.put(signature, hunks);
            }
        }
        return differing;
    }

    /** One member's hunks, each headed by its signature. */
    private static List<String> member(String signature, String note, List<List<LineDiff.Line>> hunks,
            Colours colours) {
        List<String> lines = new ArrayList<>();
        for (List<LineDiff.Line> hunk : hunks) {
            lines.add(colours.cyan("@@ " + signature + note + " @@"));
            for (LineDiff.Line line : hunk) {
                String text = line.kind() + line.text();
                lines.add(line.kind() == '-' ? colours.red(text) : line.kind() == '+' ? colours.green(text) : text);
            }
        }
        return lines;
    }

    /**
     * The file's text, without the byte-order mark Windows editors may put first (javac refuses one), read as grade
     * reads it: no further than any real Sphere.java or Renderer.java goes.
     */
    private static String read(Path file) throws IOException {
        return StudentFile.read(file);
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
        /**
         * Whether to colour: only on a console ({@code console}: standard output is not redirected)
         * that can show colours ({@code ansi}: picocli's guess, which knows the Windows consoles that
         * cannot), unless the environment {@code env} asks for none: NO_COLOR set (no-color.org), or
         * TERM=dumb (Emacs's shell, some IDEs' consoles).
         */
        static boolean wanted(boolean console, Map<String, String> env, boolean ansi) {
            String noColour = env.get("NO_COLOR");
            return console && ansi && (noColour == null || noColour.isEmpty()) && !"dumb".equals(env.get("TERM"));
        }

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
