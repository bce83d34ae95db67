package gfx.tick1.command.grade;

import gfx.tick1.command.shared.grader.cohort.StoredCode;
import gfx.tick1.engine.io.Counted;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/** What the line a stopped cohort grade ends with says of the results kept, after "tick1 grade: stopped: ". */
final class StopLine {

    private StopLine() {
    }

    /**
     * The whole line of a cohort's grade stopped with the results of {@code kept} of {@code count} submissions in
     * {@code state}; {@code count} is 0 before any submission's grade began.
     */
    static String of(Path state, int kept, int count) {
        return "tick1 grade: stopped: " + (count == 0 ? beforeAnyGrade(state) : partWay(state, kept, count));
    }

    /** The line for a grade stopped before it began to grade, with earlier runs' results, if any, in {@code state}. */
    static String beforeAnyGrade(Path state) {
        return "before any submission was graded; " + (holdsAny(state) ? "the results of earlier runs are kept in "
                + state + "; " : "") + "run the same command again to grade the rest and write the report";
    }

    /**
     * The line for a grade stopped with the results of {@code kept} of {@code submissions} in {@code state}.
     * The rest are not counted: some are never stored (a submission with files missing is checked again on
     * every run), so a count of what is left to grade would count them too.
     */
    static String partWay(Path state, int kept, int submissions) {
        return "the results of " + kept + " of " + Counted.of(submissions, "submission") + " are kept in " + state
                + "; run the same command again to grade the rest and write the report";
    }

    /** Whether {@code folder} is a folder with anything in it besides the code the look-alike check parsed. */
    private static boolean holdsAny(Path folder) {
        try (Stream<Path> entries = Files.list(folder)) {
            return entries.anyMatch(entry -> !entry.getFileName().toString().equals(StoredCode.FOLDER));
        } catch (IOException | UncheckedIOException e) {
            return false;
        }
    }
}
