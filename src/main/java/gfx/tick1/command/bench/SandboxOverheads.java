package gfx.tick1.command.bench;

import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * What the sandbox adds to each run beyond the grade's own work, timed part by part through the
 * sandbox's public calls: whole sandbox runs with and without a part differ by less than their own
 * noise on a shared machine.
 */
final class SandboxOverheads {

    private static final String TRUE = "/usr/bin/true";

    private final Sandbox sandbox;

    SandboxOverheads(Sandbox sandbox) {
        this.sandbox = sandbox;
    }

    /**
     * What a control group adds to one run in the sandbox, in seconds: the median of {@code runs}
     * times making, limiting and removing one, plus the median extra time of starting a program
     * through the shell that joins it; NaN where no group can be made. (The kernel's accounting
     * while the code runs is not in it.)
     */
    double cgroupSeconds(int runs) throws IOException, InterruptedException {
        if (!sandbox.enforcement().totals()) {
            return Double.NaN;
        }
        long[] group = new long[runs], shell = new long[runs];
        for (int i = 0; i < runs; i++) {
            long start = System.nanoTime();
            sandbox.makeAndRemoveRunGroup();
            group[i] = System.nanoTime() - start;
            shell[i] = timeStart("/bin/sh", "-c", "exec " + TRUE) - timeStart(TRUE);
        }
        return CohortTiming.median(group) + CohortTiming.median(shell);
    }

    /**
     * What its own output file system adds to one run in the sandbox, in seconds: the median of
     * {@code runs} times mounting one, counting it once as a run's end does, and unmounting it; NaN
     * where the runs' output folders are on the host's disk.
     */
    double outputDiskSeconds(int runs) throws IOException {
        if (!sandbox.enforcement().ownDisks()) {
            return Double.NaN;
        }
        Path folder = Files.createTempDirectory("tick1-disk-");
        try {
            long[] times = new long[runs];
            for (int i = 0; i < runs; i++) {
                long start = System.nanoTime();
                sandbox.mountCountAndUnmountOutputDisk(folder);
                times[i] = System.nanoTime() - start;
            }
            return CohortTiming.median(times);
        } finally {
            WorkFolder.delete(folder);
        }
    }

    /**
     * What showing a run the host's files one by one adds to it, in seconds: reading them into
     * memory before it, and starting bwrap with each bound on its own rather than all of /usr bound
     * at once (each start runs {@code true}, without limits); the medians of {@code runs} times
     * each. NaN without a sandbox.
     */
    double systemFilesSeconds(int runs) throws IOException, InterruptedException {
        if (!sandbox.enforcement().confined()) {
            return Double.NaN;
        }
        List<String> start = List.of(sandbox.bwrap().toString(), "--unshare-all", "--die-with-parent", "--proc",
                "/proc", "--dev", "/dev");
        List<String> eachFile = new ArrayList<>(start);
        eachFile.addAll(sandbox.hostFileArguments());
        eachFile.addAll(List.of("--ro-bind", TRUE, TRUE, "--", TRUE));
        List<String> allOfUsr = new ArrayList<>(start);
        allOfUsr.addAll(List.of("--ro-bind", "/usr", "/usr", "--symlink", "usr/lib", "/lib", "--symlink", "usr/lib64",
                "/lib64", "--", TRUE));
        long[] warming = new long[runs], filesStart = new long[runs], usrStart = new long[runs];
        for (int i = 0; i < runs; i++) {
            long before = System.nanoTime();
            sandbox.warmHostFiles();
            warming[i] = System.nanoTime() - before;
            filesStart[i] = timeStart(eachFile.toArray(String[]::new));
            usrStart[i] = timeStart(allOfUsr.toArray(String[]::new));
        }
        return CohortTiming.median(warming) + CohortTiming.median(filesStart) - CohortTiming.median(usrStart);
    }

    /** The wall time of {@code command}, started as the sandbox starts a run: with an environment of PATH alone. */
    private static long timeStart(String... command) throws IOException, InterruptedException {
        long start = System.nanoTime();
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD);
        builder.environment().clear();
        builder.environment().put("PATH", "/usr/bin:/bin");
        Process process = builder.start();
        process.getOutputStream().close();
        process.waitFor();
        return System.nanoTime() - start;
    }
}
