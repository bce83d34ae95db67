package gfx.tick1.engine.fast;

import java.awt.image.BufferedImage;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;

/**
 * One frame being rendered by any number of threads at once, rows in order: each thread that
 * {@linkplain #work works} on it takes the lowest row that no thread has taken yet. So the rows
 * are finished nearly top to bottom, and a PNG writer, which needs them in that order, can follow
 * the render a few rows behind instead of waiting for its end. Which thread renders a row does
 * not change its pixels: each row is traced on its own, the same way.
 *
 * <p>Except for a few rows spread down the frame, which go first: the JIT compiles the tracer
 * for what it has seen it do, and if it has seen only the top rows, which often miss every
 * sphere, it leaves out the code for a hit; the first row that meets a sphere then throws the
 * compiled code away (C2's "unstable if" trap) and it is compiled again, which is most of a
 * one-off 4K render's compilation. Rows from all over the frame show it every branch first.
 */
public final class RowsInOrder {

    private final FlatScene scene;
    private final SphereBvh tree;
    private final ScreenBounds bounds;
    private final Frame frame;
    private final int[] pixels;
    /** The rows spread down the frame that are rendered first. */
    private static final int FIRST_ROWS = 8;

    /** The rows in the order they are taken. */
    private final int[] order;
    private final AtomicInteger next = new AtomicInteger();
    private volatile boolean cancelled;

    RowsInOrder(FlatScene scene, SphereBvh tree, ScreenBounds bounds, Frame frame) {
        this.scene = scene;
        this.tree = tree;
        this.bounds = bounds;
        this.frame = frame;
        this.pixels = new int[frame.width() * frame.height()];
        this.order = order(frame.height());
    }

    /**
     * Every row once: {@link #FIRST_ROWS} rows spread evenly from the first to the last, then the
     * others from the top down.
     */
    static int[] order(int height) {
        int[] order = new int[height];
        boolean[] first = new boolean[height];
        int firstRows = height >= 4 * FIRST_ROWS ? FIRST_ROWS : 0;
        for (int k = 0; k < firstRows; k++) {
            order[k] = (int) ((long) k * (height - 1) / (firstRows - 1));
            first[order[k]] = true;
        }
        int k = firstRows;
        for (int y = 0; y < height; y++) {
            if (!first[y]) {
                order[k++] = y;
            }
        }
        return order;
    }

    /**
     * Renders rows until none is left, or until {@link #cancel}; {@code rowDone} hears the number
     * of each row this thread finished, once its pixels are written.
     */
    public void work(IntConsumer rowDone) {
        Tracer tracer = new Tracer(scene, tree, bounds, frame);
        int width = frame.width(), height = frame.height();
        for (int k = next.getAndIncrement(); k < height && !cancelled; k = next.getAndIncrement()) {
            int y = order[k];
            tracer.row(y, pixels, y * width);
            rowDone.accept(y);
        }
    }

    /** Stops the work: no thread starts another row. */
    public void cancel() {
        cancelled = true;
    }

    /** The frame as an RGB image over the rows' pixels themselves (complete once every worker has returned). */
    public BufferedImage image() {
        return FastRenderer.wrap(pixels, frame.width(), frame.height());
    }
}
