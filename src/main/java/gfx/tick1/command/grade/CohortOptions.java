package gfx.tick1.command.grade;

import gfx.tick1.command.shared.grader.report.Marking;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --submissions} and the options that go only with it: an argument group of
 * {@link GradeCommand}, handed as a value to {@link CohortCommand}.
 */
final class CohortOptions {
    @Option(names = "--submissions", paramLabel = "PATH", required = true,
            description = "Grade a whole cohort instead: PATH is Moodle's \"Download all submissions\" zip, or "
                    + "the folder it unpacks to, with one folder per student. Writes grades.csv (Moodle's "
                    + "grading worksheet), index.html, lookalikes.csv and a feedback folder per student into "
                    + "the --report folder.")
    private Path submissions;

    @Option(names = "--worksheet", paramLabel = "FILE.csv",
            description = "With --submissions: the grading worksheet downloaded from the assignment; grades.csv "
                    + "is that worksheet with the grades and feedback filled in. It is read and checked before "
                    + "anything is graded; the file itself is never changed.")
    private Path worksheet;

    @Option(names = "--jobs", paramLabel = "N",
            description = "With --submissions: how many submissions to grade at once, each in a sandbox of its "
                    + "own (default: the number of cores).")
    private int jobs = Runtime.getRuntime().availableProcessors();

    @Option(names = "--max-grade", paramLabel = "G",
            description = "With --submissions: the grade for a pass; a fail is 0 (default: the worksheet's "
                    + "Maximum Grade with --worksheet, else 1). A submission whose files could not be used "
                    + "gets a blank grade, for you to look at first.")
    private Double maxGrade;

    @Option(names = "--per-scene",
            description = "With --submissions: the grade is the share of scenes passed times --max-grade.")
    private boolean perScene;

    @Option(names = "--no-lookalikes", negatable = false,
            description = "With --submissions: skip the look-alikes (lookalikes.csv and the report's \"Look "
                    + "alike\" section: pairs of submissions whose methods share most of their tokens, or the "
                    + "same rare wrong answers, and submissions like tick1's reference).")
    private boolean noLookalikes;

    Path submissions() {
        return submissions;
    }

    /** The --worksheet given, or null. */
    Path worksheet() {
        return worksheet;
    }

    int jobs() {
        return jobs;
    }

    /** The --max-grade given, or null: the worksheet's maximum, else 1. */
    Double maxGrade() {
        return maxGrade;
    }

    /** How a result is marked: pass or fail, or with --per-scene by the scenes passed. */
    Marking marking() {
        return perScene ? Marking.PER_SCENE : Marking.PASS;
    }

    /** Whether to look for look-alikes in the cohort (on unless --no-lookalikes). */
    boolean lookalikes() {
        return !noLookalikes;
    }
}
