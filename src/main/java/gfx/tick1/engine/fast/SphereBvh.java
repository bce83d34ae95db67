package gfx.tick1.engine.fast;

import java.util.Arrays;
import java.util.Comparator;

/**
 * A bounding volume hierarchy over a scene's spheres: axis-aligned boxes split at the median
 * centroid of their longest axis, down to leaves of a few spheres.
 *
 * <p>It only decides which spheres to test; each test is {@link FlatScene#nearestRoot}, and the
 * winner is the smallest (distance, file index) pair, so the result is exactly brute force's:
 * nearest first, the earlier sphere on ties. Two things keep it conservative. Each box is padded
 * by a relative 1e-9, far more than the rounding of a computed root, so a ray that the quadratic
 * says hits a sphere never misses its box. And a node is skipped only when its box starts
 * strictly beyond the best hit so far, so an equally near sphere earlier in the file is still
 * found.
 */
final class SphereBvh {

    private static final int LEAF_SIZE = 4;

    private final FlatScene scene;
    /** Sphere indices, grouped so that every node owns a contiguous range. */
    private final int[] order;
    // Node arrays: box bounds, six a node (min x, y, z, then max x, y, z); for a leaf, the first
    // index into order and the count; for an inner node, count = 0 and the children are at
    // node + 1 and right[node].
    private final double[] bounds;
    private final int[] first, count, right;
    private int nodes;

    SphereBvh(FlatScene scene) {
        this.scene = scene;
        int capacity = Math.max(1, 2 * scene.size);
        bounds = new double[6 * capacity];
        first = new int[capacity];
        count = new int[capacity];
        right = new int[capacity];
        Integer[] boxed = new Integer[scene.size];
        for (int i = 0; i < boxed.length; i++) {
            boxed[i] = i;
        }
        build(boxed, 0, boxed.length);
        order = Arrays.stream(boxed).mapToInt(Integer::intValue).toArray();
    }

    private int build(Integer[] spheres, int from, int to) {
        int node = nodes++;
        int box = 6 * node;
        for (int axis = 0; axis < 3; axis++) {
            bounds[box + axis] = Double.POSITIVE_INFINITY;
            bounds[box + 3 + axis] = Double.NEGATIVE_INFINITY;
        }
        double[] centroids = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int k = from; k < to; k++) {
            int i = spheres[k];
            double r = scene.radius[i];
            double pad = 1e-9 * (Math.abs(scene.cx[i]) + Math.abs(scene.cy[i]) + Math.abs(scene.cz[i]) + r)
                    + Double.MIN_NORMAL;
            double[] centre = {scene.cx[i], scene.cy[i], scene.cz[i]};
            for (int axis = 0; axis < 3; axis++) {
                bounds[box + axis] = Math.min(bounds[box + axis], centre[axis] - r - pad);
                bounds[box + 3 + axis] = Math.max(bounds[box + 3 + axis], centre[axis] + r + pad);
                centroids[axis] = Math.min(centroids[axis], centre[axis]);
                centroids[axis + 3] = Math.max(centroids[axis + 3], centre[axis]);
            }
        }
        if (to - from <= LEAF_SIZE) {
            first[node] = from;
            count[node] = to - from;
            return node;
        }
        int axis = 0;
        for (int a = 1; a < 3; a++) {
            if (centroids[a + 3] - centroids[a] > centroids[axis + 3] - centroids[axis]) {
                axis = a;
            }
        }
        double[] key = axis == 0 ? scene.cx : axis == 1 ? scene.cy : scene.cz;
        Arrays.sort(spheres, from, to, Comparator.comparingDouble(i -> key[i]));
        int middle = (from + to) >>> 1;
        build(spheres, from, middle);
        right[node] = build(spheres, middle, to);
        return node;
    }

    /**
     * The index of the sphere the ray from the origin along unit D meets first, or -1.
     * {@code nodeStack} and {@code entryStack} are scratch space of at least 64 entries each,
     * one pair per thread: the nodes still to visit and where the ray enters their boxes;
     * {@code inverse} is scratch for the three components of 1 / D; the winner's distance is
     * left in {@code distance[0]}.
     */
    int closest(double dx, double dy, double dz, double a, int[] nodeStack, double[] entryStack,
            double[] inverse, double[] distance) {
        inverse[0] = 1 / dx;
        inverse[1] = 1 / dy;
        inverse[2] = 1 / dz;
        double best = Double.POSITIVE_INFINITY;
        int winner = -1;
        int top = 0;
        double rootEntry = entry(0, inverse);
        if (rootEntry == rootEntry) { // not NaN: the ray meets the root box
            nodeStack[top] = 0;
            entryStack[top++] = rootEntry;
        }
        while (top > 0) {
            int node = nodeStack[--top];
            if (entryStack[top] > best) {
                continue; // found something nearer since this node was pushed
            }
            int n = count[node];
            if (n > 0) {
                for (int k = first[node], end = first[node] + n; k < end; k++) {
                    int i = order[k];
                    double s = scene.nearestRoot(i, dx, dy, dz, a);
                    if (s < best || (s == best && i < winner)) {
                        best = s;
                        winner = i;
                    }
                }
                continue;
            }
            int near = node + 1, far = right[node];
            double nearEntry = entry(near, inverse), farEntry = entry(far, inverse);
            if (farEntry < nearEntry) {
                int swap = near;
                near = far;
                far = swap;
                double swapEntry = nearEntry;
                nearEntry = farEntry;
                farEntry = swapEntry;
            }
            // Push the far child first so that the near one is visited first; a miss (NaN) or a
            // box that starts beyond the best hit is not pushed at all.
            if (farEntry <= best) {
                nodeStack[top] = far;
                entryStack[top++] = farEntry;
            }
            if (nearEntry <= best) {
                nodeStack[top] = near;
                entryStack[top++] = nearEntry;
            }
        }
        distance[0] = best;
        return winner;
    }

    /**
     * Where a ray from the origin enters the node's box (0 if it starts inside), or NaN if it
     * misses: the slab test. A NaN from 0 * infinity (a direction component of 0 and a
     * box face at 0) never tightens the interval, which keeps the test conservative.
     */
    private double entry(int node, double[] inverse) {
        double near = 0, far = Double.POSITIVE_INFINITY;
        for (int axis = 0; axis < 3; axis++) {
            double t1 = bounds[6 * node + axis] * inverse[axis], t2 = bounds[6 * node + 3 + axis] * inverse[axis];
            if (t1 > t2) {
                double t = t1;
                t1 = t2;
                t2 = t;
            }
            if (t1 > near) {
                near = t1;
            }
            if (t2 < far) {
                far = t2;
            }
        }
        // pbrt's robust slab test widens the far bound by 2 gamma(3) for the rounding above.
        return near <= far * (1 + 2 * GAMMA_3) ? near : Double.NaN;
    }

    private static final double GAMMA_3 = 3 * Math.ulp(1.0) / 2 / (1 - 3 * Math.ulp(1.0) / 2);
}
