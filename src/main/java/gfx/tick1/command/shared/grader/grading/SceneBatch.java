package gfx.tick1.command.shared.grader.grading;

/**
 * The two batches a grade runs its scenes in, in this order, each in a run of its own: the public
 * scenes (tick1.xml, with the behaviour comparison's probes), then the hidden ones.
 */
enum SceneBatch {
    PUBLIC, HIDDEN;

    /** Whether a scene belongs to this batch. */
    boolean holds(Grading.CourseScene scene) {
        return scene.hidden() == (this == HIDDEN);
    }

    /** The folder {@link Grading#copyScenes} writes this batch's scenes to. */
    String folder() {
        return name().toLowerCase(java.util.Locale.ROOT) + "-scenes";
    }
}
