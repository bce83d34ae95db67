package gfx.tick1.fast;

/**
 * One thread's tracing state: the fast renderer's kernel. Each thread has its own, with its row
 * buffers, and traces whole rows with it.
 */
interface Tracer {

    /** Traces row y into {@code pixels} from {@code offset} on, as packed 0xRRGGBB. */
    void row(int y, int[] pixels, int offset);
}
