package gfx.tick1.command.render;

import gfx.tick1.command.shared.cli.Invocation;
import gfx.tick1.engine.render.SamplePattern;
import gfx.tick1.engine.scene.Intersection;
import java.util.Optional;

/**
 * What a render depends on, as the command line gives it: the scene file and how it is read,
 * the frame, and the threads to render with (the image is the same for any number). The output
 * and --quiet are left out: they change what is done with the image, not the image.
 *
 * @param threads the --threads given, or null for one a core
 */
public record RenderOptions(String input, boolean strict, int width, int height, int samples, Intersection intersection,
        Integer threads) {

    /** The largest width or height accepted; the frame must also fit in the JVM's heap. */
    static final int MAX_DIMENSION = 16384;

    /** The largest --threads accepted. */
    static final int MAX_THREADS = 256;

    /**
     * Written out: a record's own equals is linked on its first call through method handles
     * (ObjectMethods), which costs a one-off render several milliseconds on its critical path.
     */
    @Override
    public boolean equals(Object other) {
        return other instanceof RenderOptions o && input.equals(o.input) && strict == o.strict && width == o.width
                && height == o.height && samples == o.samples && intersection == o.intersection
                && (threads == null ? o.threads == null : threads.equals(o.threads));
    }

    @Override
    public int hashCode() {
        return ((input.hashCode() * 31 + width) * 31 + height) * 31 + samples;
    }

    /** What is wrong with these options that picocli's types cannot say (ranges, memory), if anything. */
    public Optional<String> problem() {
        if (width < 1 || width > MAX_DIMENSION) {
            return Optional.of("--width " + width + ": must be from 1 to " + MAX_DIMENSION);
        }
        if (height < 1 || height > MAX_DIMENSION) {
            return Optional.of("--height " + height + ": must be from 1 to " + MAX_DIMENSION);
        }
        if (samples < 1 || samples > SamplePattern.MAX_SAMPLES) {
            return Optional.of("--samples " + samples + ": must be from 1 to " + SamplePattern.MAX_SAMPLES);
        }
        if (threads != null && (threads < 1 || threads > MAX_THREADS)) {
            return Optional.of("--threads " + threads + ": must be from 1 to " + MAX_THREADS);
        }
        // The renderer holds the frame twice (its pixel array and the image), 4 bytes a pixel each,
        // and the PNG encoder needs room of its own: half the heap is a safe ceiling.
        long needed = 8L * width * height;
        long available = Runtime.getRuntime().maxMemory() / 2;
        if (needed > available) {
            return Optional.of(String.format("a %d x %d image needs about %d MiB, more than half of the %d MiB this "
                    + "Java may use; raise that with %s", width, height, needed >> 20,
                    Runtime.getRuntime().maxMemory() >> 20, Invocation.moreMemory()));
        }
        return Optional.empty();
    }

    /** The threads to render with: --threads, or one a core. */
    int threadCount() {
        return threads != null ? threads : Runtime.getRuntime().availableProcessors();
    }
}
