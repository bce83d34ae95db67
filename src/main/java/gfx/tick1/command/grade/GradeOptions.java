package gfx.tick1.command.grade;

import gfx.tick1.command.shared.grader.grading.Grading;
import gfx.tick1.command.shared.grader.grading.ReferenceChoice;
import java.nio.file.Path;
import java.time.Duration;
import picocli.CommandLine.Option;

/**
 * The options of every grade, one student's or a cohort's: the scenes, the report folder, the
 * limits and the size. A picocli mixin of {@link GradeCommand}, handed as a value to what grades.
 */
final class GradeOptions {

    @Option(names = "--scenes", paramLabel = "DIR",
            description = "Grade on tick1.xml and every *.xml in DIR instead of tick1.xml and the built-in hidden "
                    + "scene. The scenes of DIR are hidden: the report never quotes them and writes no images of them.")
    private Path scenesFolder;

    @Option(names = "--report", paramLabel = "DIR", defaultValue = "grade-report",
            description = "Where to write the images of failing scenes: the student's, the expected one and a heat "
                    + "map; with --submissions, the whole report and, in its state folder, every result so far "
                    + "(default: ${DEFAULT-VALUE}).")
    private Path reportFolder;

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "60",
            description = "How long the student's code may take for all scenes together, Java's start included; "
                    + "compiling may take as long again (default: ${DEFAULT-VALUE}).")
    private double timeLimitSeconds;

    @Option(names = "--memory", paramLabel = "MiB", defaultValue = "512",
            description = "The student's code's heap limit (default: ${DEFAULT-VALUE}).")
    private int memoryMegabytes;

    @Option(names = "--width", paramLabel = "PIXELS", defaultValue = "640",
            description = "Image width (default: ${DEFAULT-VALUE}, as the course grades; smaller is quicker).")
    private int width;

    @Option(names = "--height", paramLabel = "PIXELS", defaultValue = "480",
            description = "Image height (default: ${DEFAULT-VALUE}).")
    private int height;

    @Option(names = "--reference", paramLabel = "WHICH", defaultValue = "either",
            description = "Which reference image a scene must equal: handout (the handout's intersection formula in "
                    + "plain doubles), robust (tick1's own renderer, accurate where that formula is not) or either "
                    + "(default: ${DEFAULT-VALUE}). The two differ only on hard scenes, such as giant spheres.")
    private ReferenceChoice referenceChoice;

    /** The one line that says which of these options is out of its range, or null when none is. */
    String problem() {
        if (!(timeLimitSeconds > 0 && timeLimitSeconds <= 3600)) {
            return "--time-limit " + timeLimitSeconds + ": must be more than 0 and at most 3600 seconds";
        }
        if (memoryMegabytes < 32 || memoryMegabytes > 65536) {
            return "--memory " + memoryMegabytes + ": must be from 32 to 65536 MiB";
        }
        if (width < 1 || width > 4096 || height < 1 || height > 4096) {
            return "--width and --height must be from 1 to 4096, not " + width + " x " + height;
        }
        return null;
    }

    /** The --scenes folder, or null for the built-in scenes. */
    Path scenesFolder() {
        return scenesFolder;
    }

    Path reportFolder() {
        return reportFolder;
    }

    int memoryMegabytes() {
        return memoryMegabytes;
    }

    /** The limits and sizes of this grade. */
    Grading.Limits limits() {
        return new Grading.Limits(width, height, Duration.ofMillis(Math.round(timeLimitSeconds * 1000)),
                memoryMegabytes, referenceChoice);
    }
}
