package gfx.tick1.command.bench;

import gfx.tick1.engine.io.Counted;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * tick1's three speed goals, each as the ratio measured in this run beside the goal: a one-off
 * 640 x 480 render against the course's own code, a one-off 3840 x 2160 render with 4 samples
 * against a single-core scalar C tracer of the same rays, and the wall time a submission of a
 * graded cohort. A quick run measures each more coarsely (fewer runs, a smaller frame, a smaller
 * cohort), and says how: its numbers show that each goal is measured, not whether it is met.
 */
final class Goals {

    /**
     * One goal: what is measured, the value this run gives (NaN where not measured), at most what, why it was not
     * measured, and how a quick run measures it more coarsely than the full one.
     */
    record Goal(String measure, double value, double atMost, String unit, String missing, String coarser) {

        boolean measured() {
            return !Double.isNaN(value);
        }

        String valueText() {
            return measured() ? String.format(Locale.ROOT, "%.2f%s", value, unit) : "not measured";
        }

        String goalText() {
            return String.format(Locale.ROOT, "at most %.1f%s", atMost, unit);
        }

        String verdict(boolean quick) {
            if (!measured()) {
                return missing;
            }
            if (quick) {
                return "measured coarsely: " + coarser + "; not a verdict";
            }
            return value <= atMost ? "yes" : "no";
        }
    }

    private final boolean quick;
    private final List<Goal> goals = new ArrayList<>();

    /** The goals as {@code plan} measured them; {@code quick} where that is not the full plan. */
    Goals(boolean quick, BenchPlan plan, BenchCommand.Whole whole, CohortTiming.Measured cohort) {
        this.quick = quick;
        BenchPlan full = BenchPlan.FULL;
        goals.add(new Goal("tick1.xml at 640 x 480, whole run: tick1's time / the course code's",
                whole.courseCode() == null ? Double.NaN : whole.startup().median() / whole.courseCode().median(),
                0.8, "", whole.courseCodeMissing(), String.format(Locale.ROOT, "%s each, not %d",
                        Counted.of(plan.pairedRuns(), "run"), full.pairedRuns())));
        goals.add(new Goal("tick1.xml at " + whole.endToEndSize() + " with 4 samples, whole run: tick1's time / "
                + "single-core scalar C's", whole.scalarC() == null ? Double.NaN
                        : whole.endToEnd().median() / whole.scalarC().median(), 0.8, "", whole.scalarCMissing(),
                String.format(Locale.ROOT, "%d x %d, not %d x %d, where tick1's start weighs more; %s each, not %d",
                        plan.bigWidth(), plan.bigHeight(), full.bigWidth(), full.bigHeight(),
                        Counted.of(plan.bigRuns(), "run"), full.bigRuns())));
        goals.add(new Goal("grading a cohort: wall time a submission", cohort == null ? Double.NaN
                : cohort.wallPerSubmission(), 0.5, " s", "see the cohort section", String.format(Locale.ROOT,
                        "a cohort of %d, not %d, over which the grade's set-up is shared", plan.cohort(),
                        full.cohort())));
    }

    /** The report's section. */
    String markdown() {
        StringBuilder md = new StringBuilder("\n## Speed goals\n\n");
        md.append("Each ratio comes from runs taken in turn in this run (medians), so that the machine's load "
                + "falls on both sides alike.");
        if (quick) {
            md.append(" A quick run measures each goal more coarsely, as its last column says: its numbers show "
                    + "that each is measured, not whether a goal is met.");
        }
        md.append("\n\n| measure | this run | goal | met |\n| --- | ---: | --- | --- |\n");
        for (Goal goal : goals) {
            md.append("| ").append(goal.measure()).append(" | ").append(goal.valueText()).append(" | ")
                    .append(goal.goalText()).append(" | ").append(goal.verdict(quick)).append(" |\n");
        }
        return md.toString();
    }

    /** The same, as lines on the console. */
    void print(PrintWriter log) {
        log.println("speed goals (this run, then the goal):");
        for (Goal goal : goals) {
            log.printf("  %-95s %12s  %s (%s)%n", goal.measure(), goal.valueText(), goal.goalText(),
                    goal.verdict(quick));
        }
        log.flush();
    }
}
