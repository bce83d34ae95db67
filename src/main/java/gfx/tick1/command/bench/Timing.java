package gfx.tick1.command.bench;

import java.util.Arrays;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ForkJoinPool;
import java.util.function.Supplier;

/**
 * Wall-clock times of repeated runs of one task on a pool of a given size, after warm-up runs
 * that let the JIT compile the hot code: the median, and the fastest and slowest as its spread.
 */
record Timing(double[] millis) {

    static Timing of(Supplier<?> task, int threads, int warmups, int runs) {
        ForkJoinPool pool = new ForkJoinPool(threads);
        try {
            double[] millis = new double[runs];
            for (int i = -warmups; i < runs; i++) {
                // Each frame allocates its pixels anew (33 MB at 4K): collect the last frame's
                // before the clock starts, so that no run pays for another's garbage.
                System.gc();
                long start = System.nanoTime();
                // A parallel stream started inside a pool's task runs on that pool's threads.
                pool.submit(task::get).get();
                if (i >= 0) {
                    millis[i] = (System.nanoTime() - start) / 1e6;
                }
            }
            Arrays.sort(millis);
            return new Timing(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        } finally {
            pool.shutdown();
        }
    }

    static Timing of(double[] samples) {
        double[] sorted = samples.clone();
        Arrays.sort(sorted);
        return new Timing(sorted);
    }

    double median() {
        int n = millis.length;
        return n % 2 == 1 ? millis[n / 2] : (millis[n / 2 - 1] + millis[n / 2]) / 2;
    }

    double min() {
        return millis[0];
    }

    double max() {
        return millis[millis.length - 1];
    }
}
