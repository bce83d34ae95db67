package gfx.tick1.engine.fast;

import gfx.tick1.engine.render.SamplePattern;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.Scene;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;
import java.util.stream.IntStream;

/**
 * The default renderer: the same image as {@link gfx.tick1.engine.render.Renderer}, pixel for pixel,
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
     * From this many spheres on, the BVH is used: below it, brute force with the screen-space
     * rectangles is as fast or faster (docs/benchmark.md, "How the default renderer is fast").
     */
    public static final int BVH_THRESHOLD = 256;

    /** How the renderer finds the spheres a ray may meet. */
    public enum SphereSearch {
        /** The BVH from {@link #BVH_THRESHOLD} spheres on, brute force below. */
        BY_SCENE_SIZE,
        /** Every sphere whose screen rectangle holds the pixel. */
        BRUTE_FORCE,
        /** The spheres the {@link SphereBvh} chooses. */
        BVH
    }

    private final Frame frame;
    private final SphereSearch search;
    private final Intersection intersection;

    public FastRenderer(int width, int height, SamplePattern samples) {
        this(width, height, samples, Intersection.DEFAULT);
    }

    /** @param intersection how rays meet spheres, as in {@code Renderer(width, height, intersection)} */
    public FastRenderer(int width, int height, SamplePattern samples, Intersection intersection) {
        this(width, height, samples, SphereSearch.BY_SCENE_SIZE, intersection);
    }

    /**
     * @param search how to find the spheres a ray may meet
     * @param intersection how rays meet spheres, as in {@code Renderer(width, height, intersection)}
     */
    public FastRenderer(int width, int height, SamplePattern samples, SphereSearch search,
            Intersection intersection) {
        this.frame = Frame.of(width, height, samples);
        this.search = search;
        this.intersection = intersection;
    }

    public BufferedImage render(Scene scene) {
        return render(scene, row -> { });
    }

    /**
     * Renders on the current pool's threads (or the common pool and this thread, outside any pool);
     * {@code rowsDone} hears each finished row's count.
     */
    public BufferedImage render(Scene scene, IntConsumer rowsDone) {
        RowsInOrder rows = start(scene);
        AtomicInteger finished = new AtomicInteger();
        int workers = ForkJoinTask.inForkJoinPool() ? ForkJoinTask.getPool().getParallelism()
                : ForkJoinPool.getCommonPoolParallelism() + 1;
        // A parallel stream started inside a pool's task runs on that pool's threads: one worker each.
        IntConsumer counted = y -> rowsDone.accept(finished.incrementAndGet());
        IntStream.range(0, workers).parallel().forEach(worker -> rows.work(counted));
        return rows.image();
    }

    /**
     * A render of this scene that the caller's threads share, each calling {@link RowsInOrder#work}:
     * the same pixels as {@link #render(Scene)}, with the rows finished nearly in order.
     */
    public RowsInOrder start(Scene scene) {
        FlatScene flat = new FlatScene(scene, intersection);
        boolean bvh = search == SphereSearch.BVH
                || search == SphereSearch.BY_SCENE_SIZE && flat.size >= BVH_THRESHOLD;
        SphereBvh tree = bvh && flat.size > 0 ? new SphereBvh(flat) : null;
        return new RowsInOrder(flat, tree, new ScreenBounds(flat, frame), frame);
    }

    /**
     * An RGB image backed by {@code pixels} itself: copying through {@code setRGB} would convert
     * every pixel through the colour model, which costs as much as a fifth of a 4K render.
     */
    static BufferedImage wrap(int[] pixels, int width, int height) {
        DirectColorModel model = new DirectColorModel(24, 0xFF0000, 0x00FF00, 0x0000FF);
        WritableRaster raster = Raster.createPackedRaster(new DataBufferInt(pixels, pixels.length), width, height,
                width, model.getMasks(), null);
        return new BufferedImage(model, raster, false, null);
    }
}
