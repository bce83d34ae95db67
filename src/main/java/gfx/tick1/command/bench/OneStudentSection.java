package gfx.tick1.command.bench;

import gfx.tick1.command.shared.kit.StarterKit;
import gfx.tick1.engine.io.Counted;
import gfx.tick1.engine.scene.BundledScenes;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The benchmark's "one student" section: the wait between a student's edit and tick1's answer. One grade, one diff
 * and one VPL evaluation of one student's files, each in fresh processes as the student or VPL starts them, beside
 * the course's own bare work on the same correct solution (javac of the starter kit, then its main class on tick1.xml
 * and on the hidden scene, with no sandbox and no explanation); taken in turn, medians, each as a ratio to the bare
 * work, with the peak of the summed resident memory of each run's processes.
 */
final class OneStudentSection {

    /** One kind of run: how the report names it, and its goal as the most its time may be of the bare pipeline's. */
    enum Kind {
        BARE("bare pipeline", "the bare pipeline: javac of the starter kit with the correct solution, then "
                + "`java gfx.tick1.Tick1` on tick1.xml and on the hidden scene, no sandbox", Double.NaN),
        GRADE("grade, correct", "`tick1 grade`, correct solution", 1.0),
        GRADE_WRONG("grade, wrong", "`tick1 grade`, wrong solution (N.L not clamped), with its explanation", 1.3),
        DIFF("diff", "`tick1 diff`, the correct solution", 0.5),
        VPL("grade --format vpl", "`tick1 grade --format vpl`, correct solution, as VPL's activity starts it "
                + "with VPL's default limits (tick1's heap 160 MiB, the student's 64 MiB)", 1.0);

        private final String label;
        private final String words;
        private final double atMost;

        Kind(String label, String words, double atMost) {
            this.label = label;
            this.words = words;
            this.atMost = atMost;
        }
    }

    /** VPL's default memory limit, within which the summed memory of an honest evaluation stays. */
    static final double VPL_MEBIBYTES = 256;
    /** The heaps vpl_evaluate.sh gives tick1 and the student's code under that limit, in MiB. */
    private static final int VPL_OWN_HEAP = 160, VPL_STUDENT_HEAP = 64;

    /** One kind's median wall time in seconds and the largest peak of its summed memory in MiB (NaN: not read). */
    record Row(Kind kind, double medianSeconds, double peakMebibytes) {
    }

    /**
     * What was measured: how many runs of each, the rows in {@link Kind}'s order, and the machine's load average
     * before and after them, in words; or, where it could not be, no rows and why ({@code missing}).
     */
    record Measured(int runs, List<Row> rows, String missing, String load) {

        /** The ratio of a kind's median to the bare pipeline's. */
        double ratio(Row row) {
            return row.medianSeconds() / rows.get(0).medianSeconds();
        }
    }

    private OneStudentSection() {
    }

    /** Measures {@code runs} runs of each kind with {@code processes}, in {@code folder}, an empty folder. */
    static Measured measure(ProcessRuns processes, int runs, Path folder) {
        String before = CohortSection.loadAverage();
        try {
            Path tick1 = BundledScenes.extract(BundledScenes.TICK1, folder);
            Path hidden = BundledScenes.extract(BundledScenes.HIDDEN, folder);
            Path correct = student(folder.resolve("correct"), StudentSolutions.correctRenderer());
            Path wrong = student(folder.resolve("wrong"), StudentSolutions.wrongRenderer());
            String report = folder.resolve("grade-report").toString();
            List<List<ProcessRuns.Command>> sequences = new ArrayList<>();
            sequences.add(CourseCode.pipeline(folder.resolve("kit"), StarterKit.solution("Sphere"),
                    StudentSolutions.correctRenderer(), List.of(tick1, hidden)).stream()
                    .map(command -> new ProcessRuns.Command(command, 0)).toList());
            sequences.add(tick1(processes, 0, "grade", "--sphere", files(correct)[0], "--renderer", files(correct)[1],
                    "--report", report));
            sequences.add(tick1(processes, 1, "grade", "--sphere", files(wrong)[0], "--renderer", files(wrong)[1],
                    "--report", report));
            sequences.add(tick1(processes, 0, "diff", files(correct)[0], files(correct)[1]));
            // As the activity's vpl_evaluate.sh starts it with VPL's default limits (256 MiB, 240 s).
            sequences.add(List.of(processes.tick1WithHeap(VPL_OWN_HEAP, 0, "grade", "--format", "vpl",
                    "--grade-range", "0:10", "--sphere", files(correct)[0], "--renderer", files(correct)[1],
                    "--time-limit", "60", "--memory", Integer.toString(VPL_STUDENT_HEAP))));
            List<ProcessRuns.Measured> measured = processes.inTurn(runs, sequences, TreeMemory::of);
            List<Row> rows = new ArrayList<>();
            for (Kind kind : Kind.values()) {
                ProcessRuns.Measured m = measured.get(kind.ordinal());
                rows.add(new Row(kind, m.timing().median() / 1e3, m.peakMebibytes()));
            }
            return new Measured(runs, rows, null, before + " before the runs and " + CohortSection.loadAverage()
                    + " after them");
        } catch (IOException e) {
            return new Measured(runs, List.of(), e.getMessage(), null);
        }
    }

    private static List<ProcessRuns.Command> tick1(ProcessRuns processes, int exitStatus, String... args) {
        return List.of(new ProcessRuns.Command(processes.tick1Command(args), exitStatus));
    }

    /** A folder of the student's own, with the course's Sphere.java and {@code renderer} as Renderer.java. */
    private static Path student(Path folder, String renderer) throws IOException {
        Files.createDirectory(folder);
        Files.writeString(folder.resolve("Sphere.java"), StarterKit.solution("Sphere"), StandardCharsets.UTF_8);
        Files.writeString(folder.resolve("Renderer.java"), renderer, StandardCharsets.UTF_8);
        return folder;
    }

    private static String[] files(Path student) {
        return new String[] {student.resolve("Sphere.java").toString(), student.resolve("Renderer.java").toString()};
    }

    /** The report's section; {@code quick} where each run was taken fewer times than the full run takes it. */
    static String markdown(Measured m, boolean quick) {
        StringBuilder md = new StringBuilder("\n## One student\n\n");
        md.append("What a student waits for: one grade, one diff and one VPL evaluation of a Sphere.java and a "
                + "Renderer.java, each started as a fresh process as the student or VPL starts it (the sandbox "
                + "included), beside the course's own bare work on the same correct solution. The correct "
                + "Renderer.java writes the course's diffuse factor `" + StudentSolutions.DIFFUSE + "` as `"
                + StudentSolutions.DIFFUSE_OWN_WORDS + "` (the same pixels, a difference `tick1 diff` runs the "
                + "methods on); the wrong one as `" + StudentSolutions.DIFFUSE_NOT_CLAMPED + "`.");
        if (m.missing() != null) {
            return md.append("\n\nNot measured: ").append(m.missing()).append(".\n").toString();
        }
        md.append(String.format(Locale.ROOT, " %s of each, taken in turn, medians of the wall time; the memory is "
                + "the largest peak, over the runs, of the summed resident memory of the run's processes (each "
                + "process tree, read every 20 ms), as VPL counts it against its limit. The machine's load average (1 "
                + "minute) was %s: other work on the machine slows every run.", Counted.of(m.runs(), "run"), m.load()));
        if (quick) {
            md.append(" A quick run takes each once: its ratios show that each is measured, not whether a goal is "
                    + "met.");
        }
        md.append("\n\n| run | median s | ratio to the bare pipeline | goal | met | peak MiB |\n"
                + "| --- | ---: | ---: | --- | --- | ---: |\n");
        for (Row row : m.rows()) {
            boolean goal = !Double.isNaN(row.kind().atMost);
            md.append(String.format(Locale.ROOT, "| %s | %.2f | %.2f | %s | %s | %s |%n", row.kind().words,
                    row.medianSeconds(), m.ratio(row), goal ? String.format(Locale.ROOT, "at most %.1f",
                            row.kind().atMost) : "", goal ? verdict(m.ratio(row) <= row.kind().atMost, quick) : "",
                    mebibytes(row.peakMebibytes())));
        }
        Row vpl = m.rows().get(Kind.VPL.ordinal());
        if (!Double.isNaN(vpl.peakMebibytes())) {
            md.append(String.format(Locale.ROOT, "%nThe summed memory of a VPL evaluation of honest code: %.0f MiB, "
                    + "against VPL's default limit of %.0f MiB (%s).%n", vpl.peakMebibytes(), VPL_MEBIBYTES,
                    verdict(vpl.peakMebibytes() <= VPL_MEBIBYTES, quick)));
        }
        return md.toString();
    }

    private static String verdict(boolean met, boolean quick) {
        return quick ? "not a verdict" : met ? "yes" : "no";
    }

    private static String mebibytes(double value) {
        return Double.isNaN(value) ? "not read" : String.format(Locale.ROOT, "%.0f", value);
    }

    /** The same, as lines on the console. */
    static void print(Measured m, PrintWriter log) {
        if (m.missing() != null) {
            log.println("one student: not measured: " + m.missing());
        } else {
            log.printf("one student (%s each, medians; ratio to the bare pipeline, then the goal):%n",
                    Counted.of(m.runs(), "run"));
            for (Row row : m.rows()) {
                log.printf(Locale.ROOT, "  %-20s %6.2f s %6.2f %-12s %s MiB%n", row.kind().label,
                        row.medianSeconds(), m.ratio(row),
                        Double.isNaN(row.kind().atMost) ? "" : String.format(Locale.ROOT, "at most %.1f",
                                row.kind().atMost), mebibytes(row.peakMebibytes()));
            }
        }
        log.flush();
    }
}
