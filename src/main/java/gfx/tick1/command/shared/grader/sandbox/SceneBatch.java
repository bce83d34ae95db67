package gfx.tick1.command.shared.grader.sandbox;

/**
 * The two batches a grade runs its scenes in, in this order, each in a run of its own: the public
 * scenes (tick1.xml, with the behaviour comparison's probes), then the organiser's hidden ones,
 * under the stricter seccomp filter ({@link SeccompFilter}).
 */
public enum SceneBatch {
    PUBLIC, HIDDEN;

    /** The folder the grade copies this batch's scenes to. */
    public String folder() {
        return name().toLowerCase(java.util.Locale.ROOT) + "-scenes";
    }
}
