package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What a killed tick1 run left, named with its process id, is removed once that process is gone,
 * and never while it is a live Java program, as a tick1 run is.
 */
class LeftoversTest {

    @TempDir
    Path temporary;

    @Test
    void theWorkFolderAndFilterFileOfARunWhoseProcessIsGoneAreRemoved() throws Exception {
        long gone = goneProcess();
        Path work = Files.createDirectories(temporary.resolve("tick1-grade-" + gone + "-123").resolve("job-0"));
        Files.writeString(work.resolve("scene.xml"), "<scene/>");
        Path filter = Files.writeString(temporary.resolve("tick1-seccomp-" + gone + "-456.bpf"), "filter");

        assertThat(Leftovers.remove(temporary, null)).as("what could not be removed").isNull();

        assertThat(temporary).as("the temporary folder").isEmptyDirectory();
        assertThat(filter).doesNotExist();
    }

    @Test
    void whatALiveJavaProgramHoldsIsLeftAlone() throws Exception {
        long live = ProcessHandle.current().pid();   // these tests' JVM: a Java program, as tick1 is
        Path work = Files.createDirectory(temporary.resolve("tick1-grade-" + live + "-123"));
        Path filter = Files.writeString(temporary.resolve("tick1-seccomp-" + live + "-456.bpf"), "filter");

        assertThat(Leftovers.remove(temporary, null)).isNull();

        assertThat(work).as("a live run's work folder").isDirectory();
        assertThat(filter).as("a live run's filter file").exists();
    }

    @Test
    void whatAProcessIdNowTakenByAnotherProgramHoldsIsRemoved() throws Exception {
        Process sleep = new ProcessBuilder("/bin/sleep", "60").start();
        try {
            Path work = Files.createDirectory(temporary.resolve("tick1-grade-" + sleep.pid() + "-123"));

            assertThat(Leftovers.remove(temporary, null)).isNull();

            assertThat(work).as("a work folder whose process id is sleep's now").doesNotExist();
        } finally {
            sleep.destroyForcibly().waitFor();
        }
    }

    @Test
    void namesTickOneDoesNotGiveAreLeftAlone() throws Exception {
        long gone = goneProcess();
        List<Path> others = List.of(Files.createDirectory(temporary.resolve("tick1-grade123")),
                Files.createDirectory(temporary.resolve("tick1-report-" + gone + "-1")),
                Files.writeString(temporary.resolve("tick1-seccomp-" + gone + "-1.txt"), "not a filter"));

        assertThat(Leftovers.remove(temporary, null)).isNull();

        assertThat(others).as("files and folders not named as a run's").allMatch(Files::exists);
    }

    /** As root: a gone run's control group and the tmpfs mounted in its work folder go; a live run's stay. */
    @Test
    void theControlGroupsAndMountsOfARunWhoseProcessIsGoneAreRemoved() throws Exception {
        Cgroup.Place place = Cgroup.find();
        assumeThat(place).as("this process can make control groups (as root)").isNotNull();
        Path scratch = Files.createDirectory(temporary.resolve("scratch"));
        assumeThat(OutputDisk.canMount(scratch)).as("this process can mount a tmpfs (as root)").isTrue();
        long gone = goneProcess();
        long live = ProcessHandle.current().pid();
        Path output = Files.createDirectories(temporary.resolve("tick1-grade-" + gone + "-1").resolve("run"));
        OutputDisk.mount(output, 0);
        Path parent = place.parents().values().iterator().next();
        Path goneGroup = Files.createDirectory(parent.resolve("tick1-" + gone + "-1"));
        Path liveGroup = Files.createDirectory(parent.resolve("tick1-" + live + "-999999"));
        try {
            assertThat(Leftovers.remove(temporary, new Cgroup.Place(place.v2(), Map.of("", parent))))
                    .as("what could not be removed").isNull();

            assertThat(OutputDisk.mountPoints()).as("mounts").doesNotContain(output.toString());
            assertThat(output.getParent()).as("the gone run's work folder").doesNotExist();
            assertThat(goneGroup).as("the gone run's control group").doesNotExist();
            assertThat(liveGroup).as("a live run's control group").isDirectory();
        } finally {
            OutputDisk.detachAllUnder(temporary);
            Files.deleteIfExists(goneGroup);
            Files.deleteIfExists(liveGroup);
        }
    }

    /** As root: a gone run's control group that a process is still in cannot be removed, and one line says so. */
    @Test
    void whatCannotBeRemovedIsOneLineNamingIt() throws Exception {
        Cgroup.Place place = Cgroup.find();
        assumeThat(place).as("this process can make control groups (as root)").isNotNull();
        Path parent = place.parents().values().iterator().next();
        Path busy = Files.createDirectory(parent.resolve("tick1-" + goneProcess() + "-1"));
        Process sleep = new ProcessBuilder("/bin/sleep", "60").start();
        try {
            Files.writeString(busy.resolve("cgroup.procs"), Long.toString(sleep.pid()));

            String line = Leftovers.remove(temporary, new Cgroup.Place(place.v2(), Map.of("", parent)));

            assertThat(line).as("what could not be removed").isNotNull().contains(busy.toString())
                    .doesNotContain("\n");
            assertThat(busy).as("the busy control group").isDirectory();
        } finally {
            sleep.destroyForcibly().waitFor();
            for (int tries = 0; tries < 100 && Files.isDirectory(busy); tries++) {
                try {
                    Files.deleteIfExists(busy);
                } catch (IOException e) {
                    Thread.sleep(10);   // the kernel lets the group go a moment after its last process
                }
            }
        }
    }

    @Test
    void theWorkFoldersOfTheBehaviourCheckAndOfVplsScenesCheckOfARunWhoseProcessIsGoneAreRemoved() throws Exception {
        long gone = goneProcess();
        Path behaviour = Files.createDirectories(temporary.resolve("tick1-behaviour-" + gone + "-1")
                .resolve("harness"));
        Path vpl = Files.createDirectory(temporary.resolve("tick1-vpl-" + gone + "-2"));

        assertThat(Leftovers.remove(temporary, null)).as("what could not be removed").isNull();

        assertThat(behaviour.getParent()).as("the behaviour check's work folder").doesNotExist();
        assertThat(vpl).as("the work folder of tick1 vpl's check of the scenes").doesNotExist();
    }

    @Test
    void theWorkFoldersOfTheBehaviourCheckAndOfVplsScenesCheckOfALiveRunAreLeftAlone() throws Exception {
        long live = ProcessHandle.current().pid();
        Path behaviour = Files.createDirectory(temporary.resolve("tick1-behaviour-" + live + "-1"));
        Path vpl = Files.createDirectory(temporary.resolve("tick1-vpl-" + live + "-2"));

        assertThat(Leftovers.remove(temporary, null)).isNull();

        assertThat(List.of(behaviour, vpl)).as("a live run's work folders").allMatch(Files::isDirectory);
    }

    /** The line of the VPL script that makes its private folder, read from the script tick1 vpl writes. */
    private static String vplScriptsFolderLine() throws IOException {
        try (java.io.InputStream in = LeftoversTest.class.getResourceAsStream(
                "/gfx/tick1/command/shared/grader/vpl/vpl_evaluate.sh.txt")) {
            String line = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).lines()
                    .filter(text -> text.contains("private=$(mktemp")).findFirst().orElseThrow();
            return line.strip();
        }
    }

    /** Starts bash running the script's line that makes its folder in {@code temporary}, then {@code then}. */
    private Process vplScript(String then) throws IOException {
        ProcessBuilder bash = new ProcessBuilder("bash", "-c", vplScriptsFolderLine() + "; echo \"$private\"; " + then);
        bash.environment().put("TMPDIR", temporary.toString());
        return bash.start();
    }

    @Test
    void theFolderOfAVplEvaluationWhoseScriptIsGoneIsRemoved() throws Exception {
        Process script = vplScript("exit 0");
        Path folder = Path.of(new String(script.getInputStream().readAllBytes()).strip());
        assertThat(script.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(folder).as("the script's folder").isDirectory();

        assertThat(Leftovers.remove(temporary, null)).as("what could not be removed").isNull();

        assertThat(folder).as("the folder of an evaluation whose script is gone").doesNotExist();
    }

    @Test
    void theFolderOfAVplEvaluationWhoseScriptRunsIsLeftAlone() throws Exception {
        Process script = vplScript("read -r _");
        try {
            Path folder = Path.of(new java.io.BufferedReader(new java.io.InputStreamReader(script.getInputStream()))
                    .readLine());

            assertThat(Leftovers.remove(temporary, null)).isNull();

            assertThat(folder).as("the folder of an evaluation whose script runs").isDirectory();
        } finally {
            script.destroyForcibly().waitFor();
        }
    }

    /** The id of a process that has ended. */
    private static long goneProcess() throws IOException, InterruptedException {
        Process done = new ProcessBuilder("/bin/true").start();
        assertThat(done.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(Leftovers.gone(done.pid())).as("process " + done.pid() + " is gone").isTrue();
        return done.pid();
    }
}
