package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.StudentResult;

/** How a cohort's results are marked: the pass mark or none, or the share of scenes passed of it. */
public enum Marking {
    PASS, PER_SCENE;

    /**
     * The mark for {@code result} out of {@code maxGrade}; null (a blank Grade, which Moodle's upload skips) for a
     * submission never run because of a problem with its files (a missing or misnamed file, two candidates, a
     * refused zip, a participant id in two folders), and for one tick1 could not grade (its grader failed: a full
     * disk, an error of tick1's own): staff look at those first, and a 0.00 would read as a verdict on code that
     * was never tried.
     */
    public Double grade(StudentResult result, double maxGrade) {
        if (result.submission().problem() != null || !result.graded()) {
            return null;
        }
        if (this == PER_SCENE) {
            return result.scenesTotal() == 0 ? 0 : maxGrade * result.scenesPassed() / result.scenesTotal();
        }
        return result.passed() ? maxGrade : 0;
    }
}
