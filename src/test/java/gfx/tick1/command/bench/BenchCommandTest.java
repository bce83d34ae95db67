package gfx.tick1.command.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gfx.tick1.CliRun;
import gfx.tick1.command.render.RenderCommand;
import gfx.tick1.Tick1;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * {@code tick1 bench --quick} as a user runs it: in a fresh process, in a folder of its own that is not the project's,
 * with no options but --quick. It writes the three files, with a row for every variant, into its default folder.
 * What the numbers are is the report's business, not a test's.
 */
@Order(18)   // one of the longest classes: it starts early (junit-platform.properties)
class BenchCommandTest {

    @TempDir
    static Path folder;
    private static Path out;
    private static int status;
    private static String printed;

    @BeforeAll
    static void runTheQuickBenchmark() throws Exception {
        CliRun run = CliRun.inFolder(folder, "bench", "--quick");
        status = run.status();
        printed = run.out() + run.err();
        out = folder.resolve("tick1-bench");
    }

    @Test
    void exitsZeroAndSaysWhereTheReportIs() {
        assertThat(status).as(printed).isZero();
        assertThat(printed).contains("Wrote " + Path.of("tick1-bench", "report.md"));
    }

    /** The yardsticks need nothing of the project: the course code's correct solution is in the program. */
    @Test
    void theCourseCodeIsMeasuredOutsideTheProjectsFolder() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        assertThat(report).as("the course code's goal")
                .doesNotContain("| tick1.xml at 640 x 480, whole run: tick1's time / the course code's | not measured")
                .contains("| course code (starter kit + correct solution, `java -cp`), tick1.xml at 640 x 480 | ");
    }

    /** The cohort is graded in the sandbox: where none can be made, the section says why, and the test is skipped. */
    @Test
    void theCohortIsMeasuredOutsideTheProjectsFolder() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        String notMeasured = "## Grading a cohort\n\nNot measured: ";
        int at = report.indexOf(notMeasured);
        String reason = at < 0 ? "" : report.substring(at + notMeasured.length()).lines().findFirst().orElse("");
        assumeTrue(at < 0 || !reason.contains("bubblewrap"), () -> "no sandbox to grade the cohort in: " + reason);
        assertThat(report).as("the cohort's section").contains("## Grading a cohort").doesNotContain(notMeasured);
    }

    /** One student's runs are graded in the sandbox: where none can be made, the section says why instead. */
    @Test
    void theReportHasTheOneStudentSectionWithItsTableOrWhyNot() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        assertThat(report).contains("## One student")
                .containsAnyOf("| `tick1 grade`, correct solution | ", "\n\nNot measured: ");
        assertThat(printed).contains("one student");
    }

    /** The default report folder, tick1-bench, is all a run leaves in the folder it runs in. */
    @Test
    void theWorkingFolderGetsTheReportFolderAndNothingElse() throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            assertThat(files.map(file -> file.getFileName().toString())).as("the working folder")
                    .containsExactly("tick1-bench");
        }
    }

    @Test
    void aCountOfOneIsSingular() {
        assertThat(printed).contains(" 1 thread ", "max error 1 level\n").doesNotContain("1 threads", "1 levels");
    }

    @Test
    void theCsvHasARowForEveryVariantWithTimeAndError() throws IOException {
        List<String> lines = Files.readAllLines(out.resolve("results.csv"));
        assertThat(lines.get(0)).startsWith("variant,scene,width,height,samples,threads,median_ms")
                .contains("max_level_difference", "psnr_db");
        assertThat(lines).hasSize(1 + 10 + 2); // ten tick1.xml variants, brute force and BVH on the crowd
        assertThat(String.join("\n", lines)).contains("\"readable Renderer, handout formula\"", "\"float, robust\"",
                "\"fast double, robust, 16 samples\"", "\"BVH\",crowd-1000.xml");
    }

    @Test
    void theReportStatesTheMachineWhatItMeasuredAndThePlot() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        assertThat(report).contains("Machine: ", " cores", "## Whole runs in fresh processes", "10,000 spheres",
                "![speed against error]");
    }

    @Test
    void theWholeRunsTableHasTheCourseCodeAndTheCTracerBesideTick1WithRatios() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        assertThat(report).contains("| run | median ms | tick1's time / this |",
                "| course code (starter kit + correct solution, `java -cp`), tick1.xml at 640 x 480 | ",
                ScalarC.buildLine());
        assertThat(report).as("the C tracer is run where a compiler is, and says why not elsewhere")
                .containsAnyOf("| scalar C on one core, the same rays at 1920 x 1080 x 4 | ", "| scalar C: not run (");
    }

    @Test
    void theCTracerDrawsTickOnesPixelsWhereItRuns() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        String notRun = "| scalar C: not run (";
        assumeTrue(report.contains("| scalar C on one core"), () -> "the C tracer did not run: " + report.lines()
                .filter(line -> line.startsWith(notRun)).map(line -> line.substring(notRun.length(),
                        line.lastIndexOf(") |"))).findFirst().orElse("the report says not why"));
        assertThat(report).contains("The C tracer's image differs from tick1's in 0 pixels.");
    }

    @Test
    void theThreeRatiosArePrintedBesideTheirGoals() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        for (String text : new String[] {report, printed}) {
            assertThat(text).contains("640 x 480, whole run: tick1's time / the course code's",
                    "with 4 samples, whole run: tick1's time / single-core scalar C's",
                    "grading a cohort: wall time a submission", "at most 0.8", "at most 0.5 s");
        }
        assertThat(report).contains("## Speed goals", "| measure | this run | goal | met |");
    }

    /**
     * Whole runs of tick1 and the yardsticks are most of a quick run's cost: each once, tick1 and the course code twice
     * (phases, the pair of each, the handout-style run, two crowds, the big frame and the C tracer).
     */
    @Test
    void aQuickRunStartsAtMostTenFreshProcessesAndSaysHowMany() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        Matcher count = Pattern.compile("(\\d+) fresh processes in all").matcher(report);
        assertThat(count.find()).as("the report says how many fresh processes it started").isTrue();
        assertThat(Integer.parseInt(count.group(1))).as("fresh processes of a quick run").isBetween(1, 10);
        assertThat(printed).contains("fresh processes: " + count.group(1));
    }

    /** A goal that could not be measured here (no C compiler, no sandbox) says why instead. */
    @Test
    void aQuickRunSaysHowEachGoalIsMeasuredMoreCoarsely() {
        List<String> goals = printed.lines().dropWhile(line -> !line.startsWith("speed goals")).skip(1).limit(3)
                .toList();
        Map<String, String> coarser = Map.of("the course code's", "measured coarsely: 2 runs each, not 11",
                "scalar C's", "1920 x 1080, not 3840 x 2160", "a submission", "a cohort of 2, not 100");
        assertThat(goals).as("the quick run's goals on the console").hasSize(3).allSatisfy(line -> {
            if (line.contains(" not measured ")) {
                assertThat(line).as("a goal not measured").matches(".* not measured +at most [^(]+\\(.+\\)");
            } else {
                assertThat(line).as("a goal measured").contains(coarser.entrySet().stream()
                        .filter(goal -> line.contains(goal.getKey())).findFirst().orElseThrow().getValue());
            }
        });
    }

    @Test
    void aQuickRunCallsNoGoalMetOrUnmet() throws IOException {
        String report = Files.readString(out.resolve("report.md"));
        assertThat(report).doesNotContain("| yes |", "| no |");
    }

    /**
     * The scenes the run renders (about 800 KB of crowds), the yardsticks' builds and the C tracer's image (6 MB for a
     * full run) are not part of the report.
     */
    @Test
    void theReportFolderHoldsTheReportOnly() throws IOException {
        try (Stream<Path> files = Files.list(out)) {
            assertThat(files.map(file -> file.getFileName().toString()))
                    .as("the report folder").containsOnly("report.md", "results.csv", "speed-vs-error.png");
        }
    }

    @Test
    void thePlotIsAPng() throws IOException {
        assertThat(ImageIO.read(out.resolve("speed-vs-error.png").toFile())).isNotNull();
    }

    @Test
    void anUnwritableReportFolderIsOneLineAndStatusThree(@TempDir Path elsewhere) throws IOException {
        Path file = Files.writeString(elsewhere.resolve("not-a-folder"), "x");
        StringWriter err = new StringWriter();
        CommandLine commandLine = Tick1.commandLine(new RenderCommand());
        commandLine.setOut(new PrintWriter(new StringWriter(), true));
        commandLine.setErr(new PrintWriter(err, true));
        assertThat(commandLine.execute("bench", "--quick", "--out", file.resolve("report").toString())).isEqualTo(3);
        assertThat(err.toString().lines()).hasSize(1).allMatch(line -> line.startsWith("tick1 bench: "));
    }
}
