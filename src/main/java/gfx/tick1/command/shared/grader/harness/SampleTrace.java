package gfx.tick1.command.shared.grader.harness;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The pixels of a grid over the image traced again, after the student's image is written, through
 * the starter's Camera and Scene and the student's own {@code intersectionWith} and
 * {@code illuminate}, as the starter's {@code trace} does: the grader compares them with the
 * image, which must be what those methods give. One line a sample, in {@link #samples} order: the
 * colour as six hex digits, or {@code x} when the call threw. A scene whose samples do not all
 * return within {@link #SCENE_MILLIS} gets no file; one whose samples could not be traced for want of a thread
 * ({@link Bounded.Ending#NO_THREAD}) gets the one line {@link #NO_THREAD}.
 */
public final class SampleTrace {

    /** The samples' grid: this many columns and rows, at the centres of equal cells. */
    static final int COLUMNS = 16, ROWS = 12;
    /** The most the samples of one scene may take together. */
    static final long SCENE_MILLIS = 2000;
    /** The trace of a scene whose samples found no thread to be traced in. */
    public static final String NO_THREAD = "no thread";
    /** The grey a ray that meets no sphere sees, as in the starter's Renderer. */
    private static final double[] BACKGROUND = {0.1, 0.1, 0.1};

    private SampleTrace() {
    }

    /** The pixels traced for an image of this size, each as {x, y}. */
    public static List<int[]> samples(int width, int height) {
        List<int[]> pixels = new ArrayList<>();
        for (int row = 0; row < ROWS; row++) {
            for (int column = 0; column < COLUMNS; column++) {
                pixels.add(new int[] {(2 * column + 1) * width / (2 * COLUMNS), (2 * row + 1) * height / (2 * ROWS)});
            }
        }
        return pixels;
    }

    /** Traces the samples of {@code scene} (a starter Scene) and writes them to {@code file}. */
    static void trace(StarterApi api, Object scene, int width, int height, Path file) throws IOException {
        Bounded.Outcome<String> outcome = Bounded.RUN.call(() -> lines(api, scene, width, height), SCENE_MILLIS);
        if (outcome.ending() == Bounded.Ending.RETURNED) {
            Files.writeString(file, outcome.value(), StandardCharsets.UTF_8);
        } else if (outcome.ending() == Bounded.Ending.NO_THREAD) {
            Files.writeString(file, NO_THREAD + "\n", StandardCharsets.UTF_8);
        }
    }

    private static String lines(StarterApi api, Object scene, int width, int height)
            throws ReflectiveOperationException {
        Object camera = api.camera(width, height);
        Object renderer = api.renderer(width, height);
        StringBuilder text = new StringBuilder();
        for (int[] pixel : samples(width, height)) {
            String colour;
            try {
                colour = String.format("%06x", api.toRgb(colourAt(api, scene, renderer, camera, pixel)));
            } catch (RuntimeException | ReflectiveOperationException e) {
                colour = "x";
            }
            text.append(colour).append('\n');
        }
        return text.toString();
    }

    private static Object colourAt(StarterApi api, Object scene, Object renderer, Object camera, int[] pixel)
            throws ReflectiveOperationException {
        Object ray = api.castRay(camera, pixel[0], pixel[1]);
        Object hit = api.findClosestIntersection(scene, ray);
        Object object = api.objectHit(hit);
        if (object == null) {
            return api.vector(BACKGROUND);
        }
        Object colour = api.illuminate(renderer, scene, object, api.location(hit), api.normal(hit));
        if (colour == null) {
            throw new StarterApi.StudentCodeException(new NullPointerException("illuminate returned null"));
        }
        return colour;
    }
}
