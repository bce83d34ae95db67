package gfx.tick1.command.bench;

import gfx.tick1.engine.io.Counted;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/** Writes the benchmark's three files: report.md, results.csv and speed-vs-error.png. */
final class BenchReport {

    private final boolean quick;
    private final int cores;
    private final List<Result> results;
    private final Map<String, String> png;
    private final String launcher;
    private final BenchCommand.Whole whole;

    BenchReport(boolean quick, int cores, List<Result> results, Map<String, String> png, String launcher,
            BenchCommand.Whole whole) {
        this.quick = quick;
        this.cores = cores;
        this.results = results;
        this.png = png;
        this.launcher = launcher;
        this.whole = whole;
    }

    void write(Path out) throws IOException {
        Files.writeString(out.resolve("results.csv"), csv());
        Files.writeString(out.resolve("report.md"), markdown());
        BenchChart.write(results, quick, out.resolve("speed-vs-error.png"));
    }

    /** The report's title and the machine it ran on. */
    static String heading(boolean quick, int cores) {
        return "# tick1 benchmark" + (quick ? " (quick)" : "") + "\n\nMachine: " + machine(cores) + ".\n";
    }

    private static String machine(int cores) {
        return String.format(Locale.ROOT, "%s %s (%s), %s, %s %s, %s", System.getProperty("java.vm.name"),
                System.getProperty("java.version"), System.getProperty("java.vendor"),
                Counted.of(cores, "core"),
                System.getProperty("os.name"), System.getProperty("os.arch"),
                ZonedDateTime.now().format(DateTimeFormatter.ISO_OFFSET_DATE_TIME));
    }

    private String csv() {
        StringBuilder csv = new StringBuilder("variant,scene,width,height,samples,threads,median_ms,min_ms,max_ms,"
                + "mrays_per_s,error_against,error_width,error_height,max_level_difference,differing_share,psnr_db,"
                + "rms_levels\n");
        for (Result r : results) {
            csv.append(String.format(Locale.ROOT,
                    "\"%s\",%s,%d,%d,%d,%d,%.3f,%.3f,%.3f,%.3f,%s,%d,%d,%d,%.6f,%s,%.4f%n",
                    r.variant(), r.scene(), r.width(), r.height(), r.samples(), r.threads(), r.timing().median(),
                    r.timing().min(), r.timing().max(), r.megaRaysPerSecond(), r.errorAgainst(), r.errorWidth(),
                    r.errorHeight(), r.error().maxDifference(), r.differingShare(), psnr(r), r.rmsError()));
        }
        return csv.toString();
    }

    private static String psnr(Result r) {
        double psnr = r.error().psnr();
        return Double.isInfinite(psnr) ? "inf" : String.format(Locale.ROOT, "%.2f", psnr);
    }

    private String markdown() {
        StringBuilder md = new StringBuilder();
        md.append(heading(quick, cores)).append("\n");
        md.append("Each variant renders the same scene in one process, in the order listed (the default first, "
                + "before the JIT has seen the others); times are wall-clock per frame after warm-up "
                + "(median, and the fastest and slowest run as the spread). Error is measured on a smaller frame "
                + "against `truth` (the double-double TruthRenderer), against `256 samples` for anti-aliased "
                + "variants, or against `brute force` for the BVH. A crowd, `crowd-N.xml`, is a generated scene of N "
                + "spheres filling the frame (the same N always gives the same scene); the scenes are written to a "
                + "temporary folder for the run, not kept.\n\n");
        md.append("| variant | scene | frame | threads | median ms | spread ms | Mrays/s | error against | max levels "
                + "| pixels differing | PSNR dB |\n|---|---|---|---:|---:|---:|---:|---|---:|---:|---:|\n");
        for (Result r : results) {
            md.append(String.format(Locale.ROOT,
                    "| %s | %s | %d x %d%s | %d | %.1f | %.1f - %.1f | %.1f | %s | %d | %.3f%% | %s |%n",
                    r.variant(), r.scene(), r.width(), r.height(), r.samples() > 1 ? " x " + r.samples() : "",
                    r.threads(),
                    r.timing().median(), r.timing().min(), r.timing().max(), r.megaRaysPerSecond(), r.errorAgainst(),
                    r.error().maxDifference(), 100 * r.differingShare(), psnr(r)));
        }

        md.append("\nEvery double-precision variant gives the course's pixels. Where they differ from the truth by "
                + "one level, the exact value of a channel is a whole number of levels that double arithmetic lands "
                + "just below (255 x 85/255 comes out as 84.999...), and the course's images truncate it the same "
                + "way: that column measures the arithmetic's distance from exact, not a fault.\n");
        md.append("\n## PNG encoding of one frame\n\n| encoder | median | size |\n|---|---:|---:|\n");
        png.forEach((name, row) -> md.append("| ").append(name).append(" | ").append(row).append(" |\n"));

        wholeRuns(md);

        if (quick) {
            md.append("\nA quick run uses small frames and few runs: it shows that every variant runs and what it "
                    + "draws, not how fast it is.\n");
        }
        md.append("\n![speed against error](speed-vs-error.png)\n\nIn the plot each point carries its number in "
                + "the legend; points that fall together share a label (\"2, 8\"). A filled marker rendered on every "
                + "core, a hollow one on one thread.\n");
        return md.toString();
    }

    private void wholeRuns(StringBuilder md) {
        md.append("\n## Whole runs in fresh processes\n\nStarted through ").append(launcher)
                .append("; JVM start and PNG encoding included; median of the runs. ")
                .append(whole.processes()).append(" fresh processes in all")
                .append(quick ? ", each timed once (tick1 and the course code twice), with no untimed run before "
                        + "it.\n\n" : ", each command run once untimed first.\n\n");
        md.append("Where the time of one 640 x 480 render of tick1.xml goes (`tick1 --timings`, medians): the main "
                + "thread's phases (after the command line, the time it waits for each), then when the render's "
                + "own threads, started on a guess at the command line, had loaded the scene, rendered the last "
                + "row and encoded the PNG, in ms after main began:\n\n| phase | ms |\n|---|---:|\n");
        whole.phases().forEach((phase, ms) -> md.append(String.format(Locale.ROOT, "| %s | %.1f |%n", phase, ms)));
        md.append("\nThe yardsticks are run in turn with tick1's runs beside them: the course's own code (the "
                + "starter kit that `tick1 starter` writes, with a correct solution, compiled with javac and run "
                + "with `java -cp` on the same JDK) and a single-threaded scalar C tracer of the same rays with the "
                + "same maths in doubles (`" + ScalarC.SOURCE + "`, built with `" + ScalarC.buildLine() + "`).\n");
        md.append("\n| run | median ms | tick1's time / this |\n|---|---:|---:|\n");
        row(md, "tick1, tick1.xml at 640 x 480", whole.startup(), null);
        row(md, "course code (starter kit + correct solution, `java -cp`), tick1.xml at 640 x 480",
                whole.courseCode(), whole.startup());
        if (whole.courseCode() == null) {
            md.append("| course code: not run (").append(whole.courseCodeMissing()).append(") | | |\n");
        }
        row(md, "plain `java` run of a handout-style single-threaded renderer, same scene", whole.handoutStyle(),
                whole.startup());
        row(md, "tick1, 10 spheres at 640 x 480", whole.crowd10(), null);
        row(md, "tick1, 10,000 spheres at 640 x 480", whole.crowd10k(), null);
        row(md, "tick1, tick1.xml at " + whole.endToEndSize() + " with 4 samples", whole.endToEnd(), null);
        row(md, "scalar C on one core, the same rays at " + whole.endToEndSize() + " x 4", whole.scalarC(),
                whole.endToEnd());
        if (whole.scalarC() == null) {
            md.append("| scalar C: not run (").append(whole.scalarCMissing()).append(") | | |\n");
        } else {
            md.append(String.format(Locale.ROOT, "%nThe C tracer's image differs from tick1's in %,d pixels.%n",
                    whole.scalarCDiffering()));
        }
        md.append(String.format(Locale.ROOT, "%nA whole run with 10,000 spheres takes %.2f times as long as one "
                + "with 10.%n", whole.crowd10k().median() / whole.crowd10().median()));
    }

    /** A row of the whole-runs table; with {@code tick1}, the ratio of tick1's run to this one. */
    private static void row(StringBuilder md, String run, Timing timing, Timing tick1) {
        if (timing == null) {
            return;
        }
        String ratio = tick1 == null ? "" : String.format(Locale.ROOT, "%.2f", tick1.median() / timing.median());
        md.append(String.format(Locale.ROOT, "| %s | %.0f | %s |%n", run, timing.median(), ratio));
    }
}
