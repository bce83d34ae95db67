package gfx.tick1.command.shared.grader.sandbox;

/**
 * Why a scene gave no image, as the run's evidence showed it (the harness's files, the kernel's
 * counts, the clock), never as read back from the words that say it: the grade's category and a
 * hidden scene's verdict come from this.
 */
public enum NoImage {
    /** The student's code threw: the harness wrote the exception for the scene. */
    THREW,
    /** The run was stopped at the time limit, or the limit was used up before the scene. */
    TIME_LIMIT,
    /** The kernel killed a process of the run at its memory total. */
    MEMORY_LIMIT,
    /** The run reached its total of processes and threads. */
    PROCESS_LIMIT,
    /** The run was stopped at the limit of its output folder. */
    DISK_LIMIT,
    /** The program ended, or stopped at an earlier scene, or wrote an unusable image or no record of its run. */
    ENDED
}
