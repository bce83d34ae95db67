package gfx.tick1.command.bench;

import gfx.tick1.command.shared.cli.MainClass;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Whole runs of the program in fresh processes, JVM start included: what a person typing the
 * command waits for. It prefers the installed launcher ({@code bin/tick1} beside the jar's
 * {@code lib/}) and falls back to {@code java -cp} with this process's class path.
 */
final class ProcessRuns {

    private static final Pattern PHASE = Pattern.compile("\\s*([a-z ]+?) ([0-9.]+) ms");

    private final String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
    private final String classPath = System.getProperty("java.class.path");
    private final Path launcher = findLauncher();
    private final boolean warmUp;
    private int started;

    /**
     * With {@code warmUp}, each command is run once untimed before its timed runs, so that its files
     * are in the cache; without, the first run is timed too.
     */
    ProcessRuns(boolean warmUp) {
        this.warmUp = warmUp;
    }

    /** How the runs start tick1, for the report. */
    String describe() {
        return launcher != null ? "the installed launcher " + launcher : "java -cp (no installed launcher found)";
    }

    /** How many processes the runs have started so far, the untimed ones included. */
    int started() {
        return started;
    }

    /** The wall-clock times of {@code runs} runs of tick1 with these arguments. */
    Timing tick1(int runs, String... args) throws IOException {
        return time(tick1Command(args), runs);
    }

    /** The command that runs tick1 with these arguments: the launcher, or java -cp. */
    List<String> tick1Command(String... args) {
        List<String> command = new ArrayList<>();
        if (launcher != null) {
            command.add(launcher.toString());
        } else {
            command.addAll(List.of(java, "-cp", classPath, MainClass.NAME));
        }
        command.addAll(List.of(args));
        return command;
    }

    /** The wall-clock times of a plain {@code java} run of a main class on our class path. */
    Timing java(int runs, String mainClass, String... args) throws IOException {
        List<String> command = new ArrayList<>(List.of(java, "-cp", classPath, mainClass));
        command.addAll(List.of(args));
        return time(command, runs);
    }

    /**
     * The median of each phase that {@code tick1 --timings} reports over several runs, in the
     * order it reports them.
     */
    Map<String, Double> phases(int runs, String... args) throws IOException {
        Map<String, double[]> samples = new LinkedHashMap<>();
        for (int run = 0; run < runs; run++) {
            List<String> withTimings = new ArrayList<>(List.of("--timings"));
            withTimings.addAll(List.of(args));
            String err = run(tick1Command(withTimings.toArray(String[]::new)));
            String line = err.lines().filter(l -> l.startsWith("timings:")).findFirst()
                    .orElseThrow(() -> new IOException("tick1 --timings printed no timings: " + err));
            Matcher m = PHASE.matcher(line.substring("timings:".length()));
            while (m.find()) {
                samples.computeIfAbsent(m.group(1), k -> new double[runs])[run] = Double.parseDouble(m.group(2));
            }
        }
        Map<String, Double> medians = new LinkedHashMap<>();
        samples.forEach((phase, values) -> medians.put(phase, Timing.of(values).median()));
        return medians;
    }

    /** Something timed beside tick1: the command that runs it, built first; throws with the reason it cannot be. */
    interface Yardstick {
        List<String> command() throws IOException;
    }

    /**
     * The times of tick1's runs and of a yardstick's taken {@link #interleaved in turn}; or, where the yardstick
     * cannot be built or run ({@code yardstick} null), tick1's alone, with the reason in {@code missing}.
     */
    record Beside(Timing tick1, Timing yardstick, String missing) {
    }

    /** {@code runs} runs of tick1 with {@code args} beside as many of {@code yardstick}, or alone without it. */
    Beside beside(int runs, List<String> args, Yardstick yardstick) throws IOException {
        String[] tick1Args = args.toArray(String[]::new);
        try {
            List<Timing> pair = interleaved(runs, List.of(tick1Command(tick1Args), yardstick.command()));
            return new Beside(pair.get(0), pair.get(1), null);
        } catch (IOException e) {
            return new Beside(tick1(runs, tick1Args), null, e.getMessage());
        }
    }

    /**
     * The wall-clock times of {@code runs} runs of each command, taken in turn (the first command,
     * the second, ..., then the first again), so that a change in the machine's load falls on all
     * of them alike: what their ratios need.
     */
    List<Timing> interleaved(int runs, List<List<String>> commands) throws IOException {
        List<List<Command>> sequences = commands.stream().map(command -> List.of(new Command(command, 0))).toList();
        return inTurn(runs, sequences, TreeMemory::none).stream().map(Measured::timing).toList();
    }

    /** A command, the exit status it must end with, and the variables it gets beside this process's. */
    record Command(List<String> words, int exitStatus, Map<String, String> environment) {

        Command(List<String> words, int exitStatus) {
            this(words, exitStatus, Map.of());
        }
    }

    /**
     * tick1 with {@code args} and a heap of {@code heapMegabytes}, as a script that starts the launcher gives it one:
     * through TICK1_OPTS, or the option itself where tick1 is started with java -cp.
     */
    Command tick1WithHeap(int heapMegabytes, int exitStatus, String... args) {
        String heap = "-Xmx" + heapMegabytes + "m";
        if (launcher != null) {
            return new Command(tick1Command(args), exitStatus, Map.of("TICK1_OPTS", heap));
        }
        List<String> command = new ArrayList<>(List.of(java, heap, "-cp", classPath, MainClass.NAME));
        command.addAll(List.of(args));
        return new Command(command, exitStatus);
    }

    /** One kind of run measured: its times, and the largest peak of its processes' summed memory (NaN: not read). */
    record Measured(Timing timing, double peakMebibytes) {
    }

    /**
     * {@code runs} runs of each sequence, taken in turn as {@link #interleaved} takes them; a sequence's run is its
     * commands one after another, each a fresh process, timed as one. With {@code memory}
     * ({@code TreeMemory::of}), each command's processes have their resident memory read as they run.
     */
    List<Measured> inTurn(int runs, List<List<Command>> sequences, Function<Process, TreeMemory> memory)
            throws IOException {
        if (warmUp) {
            for (List<Command> sequence : sequences) {
                runAll(sequence, TreeMemory::none);
            }
        }
        double[][] millis = new double[sequences.size()][runs];
        double[] peaks = new double[sequences.size()];
        Arrays.fill(peaks, Double.NaN);
        for (int i = 0; i < runs; i++) {
            for (int c = 0; c < sequences.size(); c++) {
                Ran ran = runAll(sequences.get(c), memory);
                millis[c][i] = ran.millis();
                peaks[c] = larger(peaks[c], ran.peakMebibytes());
            }
        }
        List<Measured> measured = new ArrayList<>();
        for (int c = 0; c < sequences.size(); c++) {
            measured.add(new Measured(Timing.of(millis[c]), peaks[c]));
        }
        return measured;
    }

    /**
     * One run of tick1 with {@code args}, timed, ending with {@code exitStatus}: what it printed on standard output,
     * and its time.
     */
    Ran once(int exitStatus, String... args) throws IOException {
        return run(new Command(tick1Command(args), exitStatus), TreeMemory::none);
    }

    /**
     * A finished run: its wall-clock time, what it printed on standard output and error, and the peak of its
     * processes' summed resident memory (NaN where not read).
     */
    record Ran(double millis, String out, String err, double peakMebibytes) {
    }

    private Ran runAll(List<Command> sequence, Function<Process, TreeMemory> memory) throws IOException {
        double millis = 0, peak = Double.NaN;
        for (Command command : sequence) {
            Ran ran = run(command, memory);
            millis += ran.millis();
            peak = larger(peak, ran.peakMebibytes());
        }
        return new Ran(millis, "", "", peak);
    }

    /** The larger of two peaks, either of which may be NaN (not read). */
    private static double larger(double a, double b) {
        return Double.isNaN(a) ? b : Double.isNaN(b) ? a : Math.max(a, b);
    }

    private Timing time(List<String> command, int runs) throws IOException {
        return interleaved(runs, List.of(command)).get(0);
    }

    /** Runs a command to its end and returns what it printed on standard error. */
    private String run(List<String> command) throws IOException {
        return run(new Command(command, 0), TreeMemory::none).err();
    }

    /**
     * Runs a command to its end, timed, with its memory read as {@code memory} says; throws where it does not end with
     * its exit status, with the first line it printed on standard error.
     */
    private Ran run(Command command, Function<Process, TreeMemory> memory) throws IOException {
        started++;
        Path err = Files.createTempFile("tick1-bench", ".err"), out = Files.createTempFile("tick1-bench", ".out");
        try {
            long start = System.nanoTime();
            ProcessBuilder builder = new ProcessBuilder(command.words()).redirectError(err.toFile())
                    .redirectOutput(out.toFile());
            builder.environment().putAll(command.environment());
            Process process = builder.start();
            TreeMemory read = memory.apply(process);
            process.getOutputStream().close();
            int status = process.waitFor();
            double millis = (System.nanoTime() - start) / 1e6;
            String stderr = Files.readString(err, StandardCharsets.UTF_8);
            if (status != command.exitStatus()) {
                throw new IOException(shown(command.words()) + " exited with " + status + ": "
                        + stderr.strip().lines().findFirst().orElse("(nothing on standard error)"));
            }
            return new Ran(millis, Files.readString(out, StandardCharsets.UTF_8), stderr, read.peakMebibytes());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        } finally {
            Files.deleteIfExists(err);
            Files.deleteIfExists(out);
        }
    }

    /**
     * A command as a failure shows it, on one line: the class path, thousands of characters of the
     * libraries' paths, is left out.
     */
    private String shown(List<String> command) {
        List<String> words = new ArrayList<>(command);
        int classPathAt = words.indexOf("-cp") + 1;
        if (classPathAt > 0 && classPathAt < words.size() && words.get(classPathAt).equals(classPath)) {
            words.set(classPathAt, "(tick1's class path)");
        }
        return String.join(" ", words);
    }

    private static Path findLauncher() {
        try {
            // This class sits in the same jar as the entry point.
            Path jar = Path.of(ProcessRuns.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            Path launcher = jar.getParent().resolveSibling("bin").resolve("tick1");
            return jar.toString().endsWith(".jar") && Files.isExecutable(launcher) ? launcher : null;
        } catch (Exception e) {
            return null;
        }
    }
}
