package gfx.tick1.command.shared.grader.report;

/**
 * A student whose feedback the report could not write (a name the file system refuses, a file where their folder
 * belongs): theirs alone is missing from the report folder and feedback.zip, and the rest of the report is written.
 *
 * @param folder the student's folder, as the report names it
 * @param why    what the file system said, in one line
 */
public record Unwritten(String folder, String why) {
}
