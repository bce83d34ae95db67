package gfx.tick1.command.shared.grader.vpl;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gfx.tick1.CliRun;
import gfx.tick1.command.grade.StudentSolution;
import gfx.tick1.command.shared.grader.vpl.VplParser.Annotation;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import gfx.tick1.command.shared.grader.sandbox.SandboxNeeded;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * A Tick 1 activity's evaluation from end to end, as VPL's jail runs it (vpl-jail-system 4.x and 5.x):
 * the execution files of {@code tick1 vpl} and the student's two files in a home folder with a
 * vpl_environment.sh of VPL's variables; vpl_evaluate.sh, then the vpl_execution it leaves, run as an
 * unprivileged user with no_new_privs and only the jail's variables set (src/test/resources/vpl/jail.sh).
 * What vpl_execution printed is read as VPL reads it ({@link VplParser}). Needs root, setpriv, unshare,
 * bubblewrap and tick1 installed by {@code gradle installDist} (copied where the jail's user can run it); skipped
 * otherwise.
 */
@ExtendWith(SandboxNeeded.class)
class VplEvaluateTest {

    /** The jail's user: far from real users. */
    private static final int UID = 61_029;
    private static final Path BUILT = Path.of("build", "install", "tick1").toAbsolutePath();
    private static final String EXECUTION = "---EXECUTION---";

    @TempDir
    static Path shared;
    private static Path activity;
    /** tick1's installation, where the jail's user can run it. */
    private static Path installed;

    @TempDir
    Path dir;

    @BeforeAll
    static void writeTheActivitysExecutionFiles() throws IOException {
        assumeTrue(SandboxNeeded.root() && Files.isExecutable(Path.of("/usr/bin/setpriv")) && Files.isExecutable(
                Path.of("/usr/bin/unshare")) && Files.isExecutable(Path.of("/usr/bin/bwrap")),
                "needs root, setpriv, unshare and bubblewrap");
        assumeTrue(Files.isExecutable(BUILT.resolve("bin/tick1")), "needs tick1 installed (gradle installDist)");
        Files.setPosixFilePermissions(shared, PosixFilePermissions.fromString("rwxr-xr-x"));
        installed = copyForEveryone(BUILT, shared.resolve("tick1"));
        Path scenes = Files.createDirectories(shared.resolve("scenes"));
        Files.copy(Path.of("scenes", "no-ambient.xml"), scenes.resolve("mine.xml"));
        activity = shared.resolve("activity");
        CliRun run = CliRun.of("vpl", "--out", activity.toString(), "--scenes", scenes.toString(), "--max-grade", "7.5",
                "--tick1", installed.resolve("bin/tick1").toString());
        assertThat(run.status()).as(run.transcript()).isZero();
    }

    /**
     * A copy of the installation {@code from} at {@code to} that every user can read and run, as on a jail's host:
     * the clone that built it may lie in a folder only its owner can enter (a root's home).
     */
    private static Path copyForEveryone(Path from, Path to) throws IOException {
        try (Stream<Path> files = Files.walk(from)) {
            for (Path file : files.toList()) {
                Path copy = to.resolve(from.relativize(file).toString());
                boolean folder = Files.isDirectory(file);
                if (folder) {
                    Files.createDirectories(copy);
                } else {
                    Files.copy(file, copy);
                }
                Files.setPosixFilePermissions(copy, PosixFilePermissions.fromString(
                        folder || Files.isExecutable(file) ? "rwxr-xr-x" : "rw-r--r--"));
            }
        }
        return to;
    }

    @BeforeEach
    void openTheFolders() throws IOException {
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
    }

    /** What the evaluation printed (the Compilation section), and what vpl_execution printed, as VPL receives it. */
    private record Evaluation(String compilation, String execution, Path home) {
        String comment() {
            return VplParser.proposedComment(execution);
        }
    }

    /** Lays out the VPL home folder and runs the evaluation in the jail of {@code mode}. */
    private Evaluation evaluate(String mode, StudentSolution solution) throws IOException, InterruptedException {
        return evaluate(mode, solution, Map.of());
    }

    /**
     * Lays out the VPL home folder with the student's two files and {@code more} files they submitted (name to
     * text), and runs the evaluation in the jail of {@code mode}.
     */
    private Evaluation evaluate(String mode, StudentSolution solution, Map<String, String> more) throws IOException,
            InterruptedException {
        return evaluate(dir, mode, solution, more);
    }

    /** As {@link #evaluate(String, StudentSolution, Map)}, the home folder and the jail's script in {@code folder}. */
    private static Evaluation evaluate(Path folder, String mode, StudentSolution solution, Map<String, String> more)
            throws IOException, InterruptedException {
        Path home = Files.createDirectory(folder.resolve("p" + UID));
        try (Stream<Path> files = Files.list(activity)) {
            for (Path file : files.filter(f -> !f.getFileName().toString().equals(VplCommand.README)).toList()) {
                Files.copy(file, home.resolve(file.getFileName()), java.nio.file.StandardCopyOption.COPY_ATTRIBUTES);
            }
        }
        Map<String, String> submitted = new LinkedHashMap<>();
        submitted.put("Sphere.java", solution.sphere());
        submitted.put("Renderer.java", solution.renderer());
        submitted.putAll(more);
        for (Map.Entry<String, String> file : submitted.entrySet()) {
            Files.writeString(home.resolve(file.getKey()), file.getValue());
        }
        Files.writeString(home.resolve("vpl_environment.sh"), environment(List.copyOf(submitted.keySet())));
        chown(home);
        Path jail = folder.resolve("jail.sh");
        try (InputStream in = VplEvaluateTest.class.getResourceAsStream("/vpl/jail.sh")) {
            Files.write(jail, in.readAllBytes());
        }
        Process process = new ProcessBuilder("bash", jail.toString(), mode, home.toString(), Integer.toString(UID),
                installed.toString()).redirectErrorStream(true).start();
        process.getOutputStream().close();
        String printed = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(process.waitFor(5, TimeUnit.MINUTES)).as("the jail ends").isTrue();
        int split = printed.indexOf(EXECUTION + "\n");
        assertThat(split).as("the evaluation ran to its end:\n" + printed).isNotNegative();
        return new Evaluation(printed.substring(0, split),
                VplParser.throughPty(printed.substring(split + EXECUTION.length() + 1)), home);
    }

    /**
     * vpl_environment.sh as VPL writes it for an evaluation (moodle-mod_vpl 4.4, vpl_submission_CE.class.php's
     * prepare_execution_info and get_bash_export_for_subfiles, lib.php's vpl_bash_export): integers bare, other
     * values in single quotes (the grades come from the gradebook as text), and VPL_SUBFILES in double quotes,
     * one name a line, unescaped.
     */
    private static String environment(List<String> submitted) {
        StringBuilder text = new StringBuilder("""
                #!/bin/bash
                export VPL_LANG='en_US.UTF-8'
                export MOODLE_USER_ID=7
                export MOODLE_USER_NAME='A Student'
                export MOODLE_USER_EMAIL='student@example.org'
                export VPL_MAXTIME=240
                export VPL_MAXMEMORY=268435456
                export VPL_MAXFILESIZE=67108864
                export VPL_MAXPROCESSES=200
                export VPL_GRADEMIN='0.00000'
                export VPL_GRADEMAX='10.00000'
                export VPL_PLN='java'
                export VPL_COMPILATIONFAILED='The compilation or preparation of execution has failed'
                """);
        for (int i = 0; i < submitted.size(); i++) {
            text.append("export VPL_SUBFILE").append(i).append("='").append(submitted.get(i).replace("'", "'\\''"))
                    .append("'\n");
        }
        text.append("export VPL_SUBFILES=\"");
        submitted.forEach(name -> text.append(name).append('\n'));
        return text.append("\"\nexport VPL_VARIATION='-'\n").toString();
    }

    private static void chown(Path home) throws IOException, InterruptedException {
        Process chown = new ProcessBuilder("chown", "-R", UID + ":" + UID, home.toString()).inheritIO().start();
        assertThat(chown.waitFor()).as("chown").isZero();
    }

    private static Evaluation correctInPlainJail;

    /** The evaluation of the correct submission in the plain jail, made once: two tests read it. */
    private static synchronized Evaluation correctInPlainJail() throws IOException, InterruptedException {
        if (correctInPlainJail == null) {
            Path folder = Files.createDirectory(shared.resolve("correct"),
                    PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwxr-xr-x")));
            correctInPlainJail = evaluate(folder, "plain", StudentSolution.correct(), Map.of());
        }
        return correctInPlainJail;
    }

    @Test
    void aCorrectSubmissionGetsThePassGradeUnderAPassingTitle() throws IOException, InterruptedException {
        Evaluation evaluation = correctInPlainJail();

        assertThat(VplParser.proposedGrade(evaluation.execution())).as(evaluation.toString()).isEqualTo("7.5");
        assertThat(VplParser.titles(evaluation.comment())).as("the titles").containsExactly("Tick 1: passed");
    }

    @Test
    void theHiddenScenesAreGoneFromTheHomeFolderWhenVplExecutionRuns() throws IOException, InterruptedException {
        Evaluation evaluation = correctInPlainJail();

        try (Stream<Path> files = Files.list(evaluation.home())) {
            assertThat(files.map(f -> f.getFileName().toString()).toList()).as("the home folder's files")
                    .noneMatch(name -> name.startsWith(VplCommand.HIDDEN_PREFIX))
                    .contains("vpl_execution");
        }
    }

    @Test
    void aWrongSubmissionGetsTheMinimumWithItsReasonsAsTitles() throws IOException, InterruptedException {
        // N.L not clamped: the handout's Figure 6b.
        Evaluation evaluation = evaluate("plain", StudentSolution.correct().editRenderer("k_d * Math.max(0, NdotL)",
                "k_d * NdotL"));

        assertThat(VplParser.proposedGrade(evaluation.execution())).as(evaluation.toString()).isEqualTo("0");
        assertThat(VplParser.titles(evaluation.comment())).as("the titles").first().asString()
                .startsWith("Tick 1: failed: ");
        assertThat(VplParser.titles(evaluation.comment())).as("the titles").contains("tick1.xml: failed");
    }

    @Test
    void aCompileErrorAnnotatesItsLineInTheEditor() throws IOException, InterruptedException {
        StudentSolution solution = StudentSolution.correct().editSphere("double s = s1 > 0 ? s1 : s2;",
                "double s = s1 > 0 ? s1 : s2");
        int line = StudentSolution.sphereLineOf("double s = s1 > 0 ? s1 : s2;");
        Evaluation evaluation = evaluate("plain", solution);

        assertThat(VplParser.proposedGrade(evaluation.execution())).as(evaluation.toString()).isEqualTo("0");
        assertThat(VplParser.annotations(evaluation.comment(), List.of("Sphere.java", "Renderer.java")))
                .as("the editor's annotations").contains(new Annotation("Sphere.java", line));
    }

    @Test
    void inAMountNamespaceMadeWithPivotRootAsVpl5MakesItACorrectSubmissionPasses() throws IOException,
            InterruptedException {
        Evaluation evaluation = evaluate("pivot", StudentSolution.correct());

        assertThat(VplParser.proposedGrade(evaluation.execution())).as(evaluation.toString()).isEqualTo("7.5");
        assertThat(VplParser.titles(evaluation.comment())).as("the titles").containsExactly("Tick 1: passed");
    }

    @Test
    void inAChrootJailNothingIsGradedAndCompilationSaysWhatToChange() throws IOException, InterruptedException {
        Evaluation evaluation = evaluate("chroot", StudentSolution.correct());

        assertThat(VplParser.proposedGrade(evaluation.execution())).as(evaluation.toString()).isEmpty();
        assertThat(VplParser.titles(evaluation.comment())).as("the titles").containsExactly(VplReport.NOT_SET_UP);
        assertThat(evaluation.compilation()).as("the Compilation section")
                .contains("not set up", "vpl-jail-system 5.x", "user namespaces");
    }

    @Test
    void aThirdFileNamedToRunTheStudentsCodeRunsNothingAndProposesNoGrade() throws IOException,
            InterruptedException {
        // VPL writes the third name into VPL_SUBFILES unescaped: sourced, it would run Renderer.java as a script,
        // which this first line makes one that leaves a mark.
        StudentSolution solution = new StudentSolution(StudentSolution.correct().sphere(),
                "//bin/true; touch ran-outside-the-sandbox; exit 0\n" + StudentSolution.correct().renderer());
        Evaluation evaluation = evaluate("plain", solution, Map.of("$(bash Renderer.java)", "a third file\n"));

        assertThat(evaluation.home().resolve("ran-outside-the-sandbox")).as("what Renderer.java run as a script "
                + "leaves").doesNotExist();
        assertThat(VplParser.proposedGrade(evaluation.execution())).as(evaluation.toString()).isEmpty();
        assertThat(VplParser.titles(evaluation.comment())).as("the titles").containsExactly(VplReport.NOT_SET_UP);
        assertThat(evaluation.compilation()).as("the Compilation section").contains("maximum number of files");
    }
}
