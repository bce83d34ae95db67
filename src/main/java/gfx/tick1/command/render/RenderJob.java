package gfx.tick1.command.render;

import gfx.tick1.engine.fast.FastRenderer;
import gfx.tick1.engine.fast.RowsInOrder;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.image.RowByRowImage;
import gfx.tick1.engine.render.SamplePattern;
import gfx.tick1.engine.scene.SceneLoader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;

/**
 * One render, from the scene file to the PNG's bytes in memory, on threads of its own, so that it
 * can start before the command line is read ({@link CommandLineGuess}) and the render command
 * only collects what it made. The stages overlap: one thread loads the scene and then renders
 * with the others; another loads ImageIO's PNG writer meanwhile and encodes the rows as they are
 * finished ({@link RowByRowImage}), so that the PNG is complete soon after the last row.
 *
 * <p>Nothing here writes a file or prints a line: the command does both, once it knows that
 * this is the render it was asked for, in the order and words it always used.
 */
public final class RenderJob {

    private final RenderOptions options;
    private final long startNanos = System.nanoTime();
    private final CompletableFuture<SceneLoader> loaded = new CompletableFuture<>();
    private final CompletableFuture<RowByRowImage> started = new CompletableFuture<>();
    private final CompletableFuture<Void> rendered = new CompletableFuture<>();
    private final CompletableFuture<byte[]> png = new CompletableFuture<>();
    private final AtomicInteger rowsFinished = new AtomicInteger();
    private volatile IntConsumer progress = rows -> { };
    private volatile boolean cancelled;
    private volatile RowsInOrder rows;
    /** When each stage ended, in nanoseconds after the job started (0 until it has). */
    private volatile long loadedNanos, renderedNanos, encodedNanos;

    private RenderJob(RenderOptions options) {
        this.options = options;
    }

    /** Starts rendering what {@code options} ask for; they must have no {@link RenderOptions#problem}. */
    public static RenderJob start(RenderOptions options) {
        RenderJob job = new RenderJob(options);
        daemon("tick1-render-1", job::loadAndRender).start();
        daemon("tick1-png", job::encode).start();
        return job;
    }

    private static Thread daemon(String name, Runnable task) {
        Thread thread = new Thread(task, name);
        thread.setDaemon(true);
        return thread;
    }

    RenderOptions options() {
        return options;
    }

    /** Stops the work of a job that is not wanted after all. */
    void cancel() {
        cancelled = true;
        stopRows(new CancellationException("not the render asked for"), "not the render asked for");
    }

    /**
     * No thread starts another row; and the PNG thread, waiting for the image or its rows, is told
     * that neither will come, and why.
     */
    private void stopRows(Throwable cause, String why) {
        RowsInOrder current = rows;
        if (current != null) {
            current.cancel();
        }
        started.completeExceptionally(cause);
        started.thenAccept(image -> image.abandon(why));
    }

    private void loadAndRender() {
        SceneLoader loader;
        try {
            loader = new SceneLoader(Path.of(options.input()), options.strict());
        } catch (RuntimeException | Error e) {
            loaded.completeExceptionally(e);
            started.completeExceptionally(e);
            return;
        }
        loadedNanos = System.nanoTime() - startNanos;
        loaded.complete(loader);
        if (cancelled) {
            return;
        }
        try {
            FastRenderer renderer = new FastRenderer(options.width(), options.height(),
                    new SamplePattern(options.samples()), options.intersection());
            rows = renderer.start(loader.getScene());
            RowByRowImage image = new RowByRowImage(rows.image());
            started.complete(image);
            int threads = options.threadCount();
            AtomicInteger working = new AtomicInteger(threads);
            for (int i = 2; i <= threads; i++) {
                daemon("tick1-render-" + i, () -> work(image, working)).start();
            }
            work(image, working);
        } catch (RuntimeException | Error e) {
            fail(e);
        }
    }

    /** One render thread's share of the rows; the last to finish says the render is done. */
    private void work(RowByRowImage image, AtomicInteger working) {
        try {
            rows.work(y -> {
                image.rowDone(y);
                progress.accept(rowsFinished.incrementAndGet());
            });
        } catch (RuntimeException | Error e) {
            fail(e);
            return;
        }
        if (working.decrementAndGet() == 0 && !cancelled) {
            renderedNanos = System.nanoTime() - startNanos;
            rendered.complete(null);
        }
    }

    private void fail(Throwable e) {
        rendered.completeExceptionally(e);
        stopRows(e, e.toString());
    }

    /** Encodes the rows into PNG bytes as they are finished. */
    private void encode() {
        try {
            PngOutput.load();
            RowByRowImage image = started.join();
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            PngOutput.write(image, bytes);
            encodedNanos = System.nanoTime() - startNanos;
            png.complete(bytes.toByteArray());
        } catch (IOException | RuntimeException | Error e) {
            png.completeExceptionally(e);
        }
    }

    /** The loaded scene, once it is; throws what loading it threw (a {@code SceneException}, say). */
    SceneLoader scene() {
        return join(loaded);
    }

    /** Waits for the last row, telling {@code rowsDone} of the rows finished, from now on. */
    void awaitRender(IntConsumer rowsDone) {
        progress = rowsDone;
        rowsDone.accept(rowsFinished.get());
        try {
            rendered.join();
        } catch (CompletionException e) {
            // As a render on a pool reports its failure: the cause, in an IllegalStateException.
            throw new IllegalStateException(e.getCause());
        } finally {
            progress = rows -> { };
        }
    }

    /** The PNG, encoded at {@link PngOutput#DEFLATE_LEVEL}. */
    byte[] png() throws IOException {
        try {
            return png.join();
        } catch (CompletionException e) {
            if (e.getCause() instanceof IOException io) {
                throw io;
            }
            throw e;
        }
    }

    /**
     * For {@code --timings}: when the scene was loaded, the last row rendered and the PNG encoded,
     * in milliseconds after the job started.
     */
    String stages() {
        return String.format("scene loaded at %.1f ms, rendered at %.1f ms, encoded at %.1f ms",
                loadedNanos / 1e6, renderedNanos / 1e6, encodedNanos / 1e6);
    }

    private static <T> T join(CompletableFuture<T> future) {
        try {
            return future.join();
        } catch (CompletionException e) {
            if (e.getCause() instanceof RuntimeException runtime) {
                throw runtime;
            }
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw e;
        }
    }
}
