package gfx.tick1.fast;

import gfx.tick1.render.SamplePattern;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.Scene;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.IntConsumer;
import java.util.stream.IntStream;

/**
 * The default renderer: the same image as {@link gfx.tick1.render.Renderer}, pixel for pixel,
 * several times faster.
 *
 * <p>It performs exactly the readable code's floating-point operations in the same order (the
 * camera's, the intersection method's and {@code Renderer.illuminate}'s), but on bare doubles
 * instead of a new {@code Vector3} per step, a row at a time in passes (a {@link Tracer}), with
 * the ray-independent terms of each sphere computed once ({@link FlatScene}), a rectangle of the
 * image outside which a sphere is not tested ({@link ScreenBounds}) and, for scenes with many
 * spheres, a BVH choosing which spheres to test ({@link SphereBvh}). The readable code is its
 * test oracle: the two must agree on every pixel of every scene in the repository.
 */
public final class FastRenderer {

    /**
     * From this many spheres on, the BVH is used. Measured on the benchmark's crowd scenes at
     * 640 x 480, one core, median of 7: brute force with the screen-space rectangles is faster up
     * to 128 spheres (25 against 45 ms at 64, 37 against 42 at 128), level at 256 (57 against
     * 56), and the BVH pulls ahead beyond (107 against 83 at 512).
     */
    public static final int BVH_THRESHOLD = 256;

    /**
     * The {@link VectorTracer} is used for frames at least this wide, once this process has
     * traced {@link #VECTOR_AFTER_RAYS} rays; otherwise the {@link ScalarTracer}. Both give the
     * same pixels; they differ in when they are fast. Measured on tick1.xml, two threads, after
     * 30 renders (median of the last 10), scalar against vector: 6 against 10.5 ms at 640 x 480,
     * 15 against 12.5 at 1280 x 720, 30 against 17 at 1920 x 1080, 83 against 49 at 2560 x 1440,
     * 116 against 76 at 3840 x 2160. The vector tracer's passes cost a little per row, which
     * narrow rows do not repay.
     */
    public static final int VECTOR_MIN_WIDTH = 1280;

    /**
     * The vector tracer is many short loops that C2 unrolls and vectorises, which costs the
     * compiler about half a second of a core, and until then it runs slower than the scalar
     * tracer: a single render in a fresh JVM took, median of 5, 627 against 386 ms at 3840 x
     * 2160, and 872 against 668 ms with 4 samples. A one-off render (the command line) never
     * earns that back; a process that renders again and again (the benchmark, the preview,
     * grading) does. So the first renders of a process use the scalar tracer.
     */
    public static final long VECTOR_AFTER_RAYS = 5_000_000;

    /** Rays traced by fast renderers in this process so far: how warm the JIT is. */
    private static final AtomicLong RAYS_TRACED = new AtomicLong();

    private final Frame frame;
    private final Boolean forceBvh, forceVector;
    private final Intersection intersection;

    public FastRenderer(int width, int height, SamplePattern samples) {
        this(width, height, samples, null, Intersection.DEFAULT);
    }

    /**
     * @param bvh force the BVH on (true) or off (false), or null to choose by scene size
     * @param intersection how rays meet spheres, as in {@code Renderer(width, height, intersection)}
     */
    public FastRenderer(int width, int height, SamplePattern samples, Boolean bvh, Intersection intersection) {
        this(width, height, samples, bvh, intersection, null);
    }

    /**
     * @param vector force the {@link VectorTracer} (true) or the {@link ScalarTracer} (false), or
     *     null to choose by {@link #VECTOR_MIN_WIDTH} and {@link #VECTOR_AFTER_RAYS}
     */
    public FastRenderer(int width, int height, SamplePattern samples, Boolean bvh, Intersection intersection,
            Boolean vector) {
        this.frame = Frame.of(width, height, samples);
        this.forceBvh = bvh;
        this.forceVector = vector;
        this.intersection = intersection;
    }

    public BufferedImage render(Scene scene) {
        return render(scene, row -> { });
    }

    /** Renders on the current pool's threads; {@code rowsDone} hears each finished row's count. */
    public BufferedImage render(Scene scene, IntConsumer rowsDone) {
        FlatScene flat = new FlatScene(scene, intersection);
        boolean bvh = forceBvh != null ? forceBvh : flat.size >= BVH_THRESHOLD;
        SphereBvh tree = bvh && flat.size > 0 ? new SphereBvh(flat) : null;
        ScreenBounds bounds = new ScreenBounds(flat, frame);
        int width = frame.width(), height = frame.height();
        int[] pixels = new int[width * height];
        AtomicInteger finished = new AtomicInteger();
        boolean warm = RAYS_TRACED.getAndAdd(frame.rays()) >= VECTOR_AFTER_RAYS;
        boolean vector = forceVector != null ? forceVector : warm && width >= VECTOR_MIN_WIDTH;
        // One tracer (and its row buffers) a thread, not a row.
        ThreadLocal<Tracer> tracers = ThreadLocal.withInitial(() -> vector
                ? new VectorTracer(flat, tree, bounds, frame)
                : new ScalarTracer(flat, tree, bounds, frame));
        IntStream.range(0, height).parallel().forEach(y -> {
            tracers.get().row(y, pixels, y * width);
            rowsDone.accept(finished.incrementAndGet());
        });
        return wrap(pixels, width, height);
    }

    /**
     * An RGB image backed by {@code pixels} itself: copying through {@code setRGB} would convert
     * every pixel through the colour model, which costs as much as a fifth of a 4K render.
     */
    private static BufferedImage wrap(int[] pixels, int width, int height) {
        DirectColorModel model = new DirectColorModel(24, 0xFF0000, 0x00FF00, 0x0000FF);
        WritableRaster raster = Raster.createPackedRaster(new DataBufferInt(pixels, pixels.length), width, height,
                width, model.getMasks(), null);
        return new BufferedImage(model, raster, false, null);
    }
}
