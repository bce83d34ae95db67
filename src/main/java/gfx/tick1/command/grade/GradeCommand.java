package gfx.tick1.command.grade;

import gfx.tick1.command.shared.cli.CommandFailure;
import gfx.tick1.command.shared.cli.ExitStatus;
import gfx.tick1.command.shared.cli.OutputGate;
import gfx.tick1.command.shared.cli.StopSignal;
import gfx.tick1.command.shared.cli.TemporaryFolder;
import gfx.tick1.command.shared.coverage.ScenesShortfall;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.vpl.GradeRange;
import gfx.tick1.command.shared.grader.vpl.VplReport;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code tick1 grade}: the course's tester, with reasons. Compiles a student's two files against
 * the starter code, renders the grading scenes with them in a separate JVM, and compares each
 * image with the reference render.
 */
@Command(name = "grade",
        description = {
            "Grades a student's Sphere.java and Renderer.java as the course's tester does, or a whole cohort "
                    + "from Moodle's download.",
            "It compiles the two files with the starter code (see tick1 starter), renders tick1.xml and a hidden "
                    + "scene (or the scenes given) with them, and compares each image with the reference render, "
                    + "pixel for pixel. Compiling and rendering run in a separate Java process inside a bubblewrap "
                    + "sandbox, with time, memory and process limits. A failing scene is explained: the difference "
                    + "figures, the closest entry of the diagnose catalogue, and a heat map; of a hidden scene only "
                    + "its verdict is said, in fixed words. "
                    + "The built-in hidden scene is public (it is in tick1, which students have): anyone can pass it "
                    + "by copying its images; give scenes of your own with --scenes for a grade that counts.",
            "With --submissions it grades a whole cohort from Moodle's download: every submission in a sandbox of "
                    + "its own, several at once, into grades.csv (Moodle's grading worksheet), a feedback page per "
                    + "student and index.html. Each result is kept as soon as it is known: a grade that is stopped "
                    + "loses nothing, and running it again grades only what is new or changed.",
            "Trust: inside the sandbox the student's code sees no file of yours but the scenes, has no network and "
                    + "cannot outlive the grade. It needs Linux and the bubblewrap package; --no-sandbox runs the "
                    + "code with your permissions instead."})
public final class GradeCommand implements Callable<Integer> {

    @ExitStatus("the code passed: every scene matches pixel for pixel; with --submissions: every submission was "
            + "graded and the report written, whatever the students' results")
    public static final int EXIT_PASS = 0;
    @ExitStatus("the code failed: it does not compile, crashed, ran out of time or memory, or an image is wrong")
    public static final int EXIT_FAIL = 1;
    @ExitStatus("the command line is wrong, or a file given, the temporary folder or the sandbox is unusable")
    public static final int EXIT_USAGE = 2;
    @ExitStatus("a scene failed and its images could not be written to the report folder; with --submissions: the "
            + "report could not be written, or a submission's result could not be stored")
    public static final int EXIT_CANNOT_WRITE = 3;
    @ExitStatus("with --submissions: the report is written, but some submissions were not graded because the "
            + "grader ran short of its own disk or memory (standard error names them): free some, and the same "
            + "command grades them")
    public static final int EXIT_NOT_GRADED = 5;
    @ExitStatus("stopped by Ctrl-C or SIGTERM; with --submissions: the results finished so far are kept, and the same "
            + "command grades the rest")
    public static final int EXIT_STOPPED = 130;

    @Spec
    private CommandSpec spec;

    /** Whom to grade: one student's two files, or a cohort's download; picocli allows one or the other. */
    @ArgGroup(exclusive = true, multiplicity = "0..1")
    private Target target;

    /** One student, or a cohort: the two are exclusive, and the cohort's options go only with the cohort. */
    static final class Target {
        @ArgGroup(exclusive = false, multiplicity = "1")
        private OneStudent student;

        @ArgGroup(exclusive = false, multiplicity = "1")
        private CohortOptions cohort;
    }

    /** {@code --sphere} and {@code --renderer}, both needed. */
    static final class OneStudent {
        @Option(names = "--sphere", paramLabel = "Sphere.java", required = true,
                description = "The student's Sphere.java.")
        private Path sphere;

        @Option(names = "--renderer", paramLabel = "Renderer.java", required = true,
                description = "The student's Renderer.java.")
        private Path renderer;
    }

    /** The options of every grade: the scenes, the report folder, the limits and the size. */
    @Mixin
    private GradeOptions options;

    /** What one student's grade prints: tick1's own report, or VPL's evaluation format. */
    enum Format { text, vpl }

    @Option(names = "--format", paramLabel = "FORMAT", defaultValue = "text",
            description = "With --sphere and --renderer: text (default), or vpl: the report in the format of Moodle's "
                    + "Virtual Programming Lab's evaluation, with the proposed grade as its last line, for the "
                    + "activity's vpl_execution (see tick1 vpl). Where the sandbox cannot be made it proposes no "
                    + "grade. It writes no images.")
    private Format format;

    @Option(names = "--grade-range", paramLabel = "MIN:MAX", defaultValue = "0:1",
            description = "With --format vpl: the grade of a fail and of a pass, the activity's VPL_GRADEMIN and "
                    + "VPL_GRADEMAX (default: ${DEFAULT-VALUE}).")
    private String gradeRange;

    @Option(names = "--no-sandbox",
            description = "Run the student's code without the sandbox, in a Java process limited only in time and "
                    + "heap, with your permissions, your files and the network: for your own code where bubblewrap "
                    + "cannot run (macOS, Windows), or code you trust. Not with --format vpl.")
    private boolean noSandbox;

    /** Shut when a stop has been said: nothing the grade's threads print comes after that line. */
    private OutputGate gate;
    /** The grade's stop, which says that it stopped and undoes what the grade began. */
    private GradeStop stop;

    @Override
    public Integer call() throws IOException, InterruptedException {
        String usage = checkOptions();
        if (usage != null) {
            throw new ParameterException(spec.commandLine(), usage);
        }
        // Every line of the grade passes the gate, the one-line errors that tick1's start-up prints included.
        gate = new OutputGate(spec.commandLine().getErr());
        PrintWriter out = gate.wrap(spec.commandLine().getOut());
        PrintWriter err = gate.wrap(spec.commandLine().getErr());
        spec.commandLine().setOut(out).setErr(err);
        // A stop is said from the start (SIGTERM's status is set once it can be); a cohort says how many results
        // it kept, once it has any.
        stop = GradeStop.saying(gate, target.cohort != null ? StopLine.of(options.reportFolder()
                .resolve(CohortCommand.STATE_FOLDER), 0, 0) : StudentGrade.STOPPED_LINE);
        StopSignal.exitOnSigterm(EXIT_STOPPED);
        try {
            return format == Format.vpl ? vplEvaluation(out, err) : call(out, err);
        } finally {
            stop.end(() -> { });
            // The gate passes text on unflushed, and tick1 ends with System.exit: whatever way the grade ends,
            // what it printed is written out (after a stop, the gate is shut and this does nothing).
            out.flush();
            err.flush();
        }
    }

    /**
     * {@code --format vpl}: one student's grade as VPL's evaluation. Where tick1 cannot grade (no sandbox can be
     * made, a file or a scene cannot be read), the report says so and proposes no grade, and the reason goes, as
     * ever, to the standard error, which the activity's vpl_evaluate.sh shows to staff. It never runs the code
     * without the sandbox: its hidden scenes and its report would be in the student's reach.
     */
    private Integer vplEvaluation(PrintWriter out, PrintWriter err) throws IOException, InterruptedException {
        try {
            return call(out, err);
        } catch (CommandFailure | IOException e) {
            out.print(VplReport.notSetUp());
            out.flush();
            throw e;
        }
    }

    /** Why the options do not go with --format vpl, or null. */
    private String vplOptionsProblem() {
        if (target == null || target.student == null) {
            return "--format vpl grades one student: give --sphere and --renderer";
        }
        if (noSandbox) {
            return "--format vpl never runs a student's code without the sandbox: leave out --no-sandbox";
        }
        try {
            GradeRange.parse(gradeRange);
        } catch (IllegalArgumentException e) {
            return "--grade-range " + gradeRange + ": " + e.getMessage();
        }
        return null;
    }

    /**
     * The grade, with the checks of the options done: in tick1's own format, or with --format vpl's sandbox. What
     * the sandbox does not hold the code to here is said once, after the grade's own answer: it qualifies a grade,
     * and a grade that ends in a one-line error graded nothing.
     */
    private Integer call(PrintWriter out, PrintWriter err) throws IOException, InterruptedException {
        TemporaryFolder.problem().ifPresent(problem -> {
            throw new CommandFailure(EXIT_USAGE, problem);
        });
        // A cohort's stop is said from the start: the sandbox is made once the cohort has its stop line ready.
        Sandbox[] made = new Sandbox[1];
        CohortCommand.Sandboxes sandboxes = () -> made[0] = hiding(sandbox(err));
        int status = target.cohort != null ? new CohortCommand(options, target.cohort, out, err, stop).call(sandboxes)
                : new StudentGrade(options, target.student.sphere, target.student.renderer, vpl() ? gradeRange() : null,
                        sandboxes.make(), stop).call(out, err);
        Sandbox sandbox = made[0];
        ScenesShortfall.of(vpl() ? null : options.scenesFolder(), options.limits().width(), options.limits().height())
                .ifPresent(shortfall -> err.println("tick1 grade: warning: " + shortfall.line(options.scenesFolder())));
        sandbox.enforcement().warnings().forEach(warning -> err.println("tick1 grade: warning: " + warning));
        return status;
    }

    /** No sandbox, with --no-sandbox (said at once, before the student's code runs), or bubblewrap's. */
    private Sandbox sandbox(PrintWriter err) throws InterruptedException {
        if (noSandbox) {
            err.println("tick1 grade: warning: --no-sandbox: the student's code runs with your permissions, without "
                    + "a sandbox, in a Java process limited only in time (--time-limit) and heap (--memory); it can "
                    + "read, change and send anything you can");
            return Sandbox.unconfined();
        }
        try {
            return Sandbox.confined();
        } catch (Sandbox.Unavailable e) {
            // --no-sandbox is offered only where it is allowed: one student's files, not VPL or a cohort.
            List<String> remedies = new ArrayList<>();
            if (e.remedy() != null) {
                remedies.add(e.remedy());
            }
            if (!vpl() && target.cohort == null) {
                remedies.add("give --no-sandbox to grade without a sandbox");
            }
            throw new CommandFailure(EXIT_USAGE, e.getMessage() + (remedies.isEmpty() ? "" : ": "
                    + String.join(", or ", remedies)));
        }
    }

    /** {@code sandbox}, hiding the --scenes folder when one is given. */
    private Sandbox hiding(Sandbox sandbox) throws IOException {
        if (options.scenesFolder() == null) {
            return sandbox;
        }
        try {
            return sandbox.hiding(organisersScenes());
        } catch (Sandbox.CannotHide e) {
            throw new CommandFailure(EXIT_USAGE, e.getMessage());
        }
    }

    static void reportUndeleted(String problem, PrintWriter err) {
        if (problem != null) {
            err.println("tick1 grade: " + problem);
            err.flush();
        }
    }

    private String checkOptions() {
        if (target == null) {
            return "give --sphere and --renderer (one student), or --submissions (a cohort)";
        }
        if (noSandbox && target.cohort != null) {
            return "--submissions never runs students' code without the sandbox: leave out --no-sandbox, which "
                    + "is for one student's code that is yours";
        }
        int jobs = jobs();
        double maxGrade = maxGrade() == null ? 1 : maxGrade();
        if (jobs < 1 || jobs > Sandbox.MOST_JOBS) {
            return "--jobs " + jobs + ": must be from 1 to " + Sandbox.MOST_JOBS;
        }
        if (!(maxGrade > 0 && maxGrade <= 1_000_000)) {
            return "--max-grade " + maxGrade + ": must be more than 0 and at most 1000000";
        }
        String problem = options.problem();
        if (problem != null) {
            return problem;
        }
        return format == Format.vpl ? vplOptionsProblem() : null;
    }

    private boolean vpl() {
        return format == Format.vpl;
    }

    /** The --grade-range, checked by {@link #checkOptions()} first. */
    private GradeRange gradeRange() {
        return GradeRange.parse(gradeRange);
    }

    /**
     * The --scenes folder and the files in it, for the sandbox to hide: each file stands for the
     * folder it really is in, which a link may put elsewhere.
     */
    private List<Path> organisersScenes() throws IOException {
        Path scenesFolder = options.scenesFolder();
        List<Path> scenes = new ArrayList<>(List.of(scenesFolder));
        if (Files.isDirectory(scenesFolder)) {
            try (var files = Files.list(scenesFolder)) {
                files.forEach(scenes::add);
            }
        }
        return scenes;
    }

    /** The --jobs given, for the check of the options; the number of cores for one student. */
    private int jobs() {
        return target == null || target.cohort == null ? Runtime.getRuntime().availableProcessors()
                : target.cohort.jobs();
    }

    /** The --max-grade given, or null, for the check of the options. */
    private Double maxGrade() {
        return target == null || target.cohort == null ? null : target.cohort.maxGrade();
    }
}
