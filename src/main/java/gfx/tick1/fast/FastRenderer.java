package gfx.tick1.fast;

import gfx.tick1.math.Vector3;
import gfx.tick1.render.SamplePattern;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.Scene;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;
import java.util.stream.IntStream;

/**
 * The default renderer: the same image as {@link gfx.tick1.render.Renderer}, pixel for pixel,
 * several times faster.
 *
 * <p>It performs exactly the readable code's floating-point operations in the same order (the
 * camera's, {@code Sphere.intersectionWith}'s and {@code Renderer.illuminate}'s), but on bare
 * doubles instead of a new {@code Vector3} per step, with the ray-independent terms of each
 * sphere computed once ({@link FlatScene}) and, for scenes with many spheres, a BVH choosing
 * which spheres to test ({@link SphereBvh}). The readable code is its test oracle: the two must
 * agree on every pixel of every scene in the repository.
 */
public final class FastRenderer {

    /**
     * From this many spheres on, the BVH is used. Measured on the benchmark's crowd scenes at
     * 640 x 480, one core: brute force is as fast or faster up to about 100 spheres (the tree's
     * box tests cost about what they save), the BVH three times faster at 1,000.
     */
    public static final int BVH_THRESHOLD = 64;

    private static final int BACKGROUND = new Vector3(0.1).toRGB();

    private final int width, height;
    private final SamplePattern samples;
    private final Boolean forceBvh;
    private final Intersection intersection;
    private final double widthM, heightM, xStep, yStep;

    public FastRenderer(int width, int height, SamplePattern samples) {
        this(width, height, samples, null, Intersection.DEFAULT);
    }

    /**
     * @param bvh force the BVH on (true) or off (false), or null to choose by scene size
     * @param intersection how rays meet spheres, as in {@code Renderer(width, height, intersection)}
     */
    public FastRenderer(int width, int height, SamplePattern samples, Boolean bvh, Intersection intersection) {
        this.width = width;
        this.height = height;
        this.samples = samples;
        this.forceBvh = bvh;
        this.intersection = intersection;
        // The Camera's arithmetic, step for step.
        double aspectRatio = (double) width / (double) height;
        widthM = 2 * Math.tan(Math.toRadians(45) / 2);
        heightM = widthM / aspectRatio;
        xStep = widthM / width;
        yStep = heightM / height;
    }

    public BufferedImage render(Scene scene) {
        return render(scene, row -> { });
    }

    /** Renders on the current pool's threads; {@code rowsDone} hears each finished row's count. */
    public BufferedImage render(Scene scene, IntConsumer rowsDone) {
        FlatScene flat = new FlatScene(scene, intersection);
        boolean bvh = forceBvh != null ? forceBvh : flat.size >= BVH_THRESHOLD;
        SphereBvh tree = bvh && flat.size > 0 ? new SphereBvh(flat) : null;
        ScreenBounds bounds = new ScreenBounds(flat, widthM, heightM, xStep, yStep);
        int[] pixels = new int[width * height];
        AtomicInteger finished = new AtomicInteger();
        // One tracer (and its row buffers) a thread, not a row.
        ThreadLocal<Tracer> tracers = ThreadLocal.withInitial(() -> new Tracer(flat, tree, bounds));
        IntStream.range(0, height).parallel().forEach(y -> {
            Tracer tracer = tracers.get();
            if (samples.size() == 1) {
                tracer.row(y, pixels, y * width);
            } else {
                for (int x = 0; x < width; x++) {
                    pixels[y * width + x] = tracer.pixel(x, y);
                }
            }
            rowsDone.accept(finished.incrementAndGet());
        });
        return wrap(pixels, width, height);
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

    /** One thread's tracing state: the colour of the last ray and scratch space for the BVH. */
    private final class Tracer {

        private final FlatScene scene;
        private final SphereBvh tree;
        private final ScreenBounds bounds;
        private final int[] nodeStack = new int[64];
        private final double[] entryStack = new double[64];
        private final double[] inverse = new double[3];
        private final double[] distance = new double[1];
        private double red, green, blue;

        Tracer(FlatScene scene, SphereBvh tree, ScreenBounds bounds) {
            this.scene = scene;
            this.tree = tree;
            this.bounds = bounds;
        }

        // One sample a pixel: the row in three passes (the rays' directions, their nearest hits,
        // the shading of the hits). A pixel's work is one long chain of dependent divisions and
        // square roots; split into passes, the chains of neighbouring pixels are independent and
        // the processor overlaps them. Measured at 4K: 308 -> 260 ms on one core.
        private final int[] rowHit = new int[width];
        private final double[] rowS = new double[width];
        private final double[] rowDx = new double[width], rowDy = new double[width], rowDz = new double[width];

        void row(int y, int[] pixels, int offset) {
            double py = (yStep + heightM) / 2 - y * yStep;
            for (int x = 0; x < width; x++) {
                double px = (xStep - widthM) / 2 + x * xStep;
                double length = Math.sqrt(px * px + py * py + 1 * 1);
                rowDx[x] = px / length;
                rowDy[x] = py / length;
                rowDz[x] = 1 / length;
            }
            for (int x = 0; x < width; x++) {
                rowHit[x] = nearest(x, y, rowDx[x], rowDy[x], rowDz[x]);
                rowS[x] = hitDistance;
            }
            for (int x = 0; x < width; x++) {
                if (rowHit[x] < 0) {
                    pixels[offset + x] = BACKGROUND;
                } else {
                    shade(rowHit[x], rowS[x], rowDx[x], rowDy[x], rowDz[x]);
                    pixels[offset + x] = toRGB(red, green, blue);
                }
            }
        }

        private double hitDistance, hitDx, hitDy, hitDz;

        int pixel(int x, int y) {
            if (samples.size() == 1) {
                return trace(x, y) ? toRGB(red, green, blue) : BACKGROUND;
            }
            double sumRed = 0, sumGreen = 0, sumBlue = 0;
            for (int i = 0; i < samples.size(); i++) {
                if (!trace(x + samples.dx(i), y + samples.dy(i))) {
                    red = green = blue = 0.1;
                }
                // The readable code starts its sum from the first sample; 0 + v is v for v != -0,
                // and colours are never -0 (each channel is a sum with a non-negative term first).
                sumRed += red;
                sumGreen += green;
                sumBlue += blue;
            }
            double scale = 1.0 / samples.size();
            return toRGB(scale * sumRed, scale * sumGreen, scale * sumBlue);
        }

        /** Traces the ray through (x, y) in pixels; false for a miss, else the colour in red, green, blue. */
        private boolean trace(double x, double y) {
            int hit = nearest(x, y);
            if (hit < 0) {
                return false;
            }
            shade(hit, hitDistance, hitDx, hitDy, hitDz);
            return true;
        }

        /** The sphere the ray through (x, y) meets first, or -1; its distance and direction in the fields. */
        private int nearest(double x, double y) {
            double px = (xStep - widthM) / 2 + x * xStep;
            double py = (yStep + heightM) / 2 - y * yStep;
            double length = Math.sqrt(px * px + py * py + 1 * 1);
            return nearest(x, y, px / length, py / length, 1 / length);
        }

        private int nearest(double x, double y, double dx, double dy, double dz) {
            double a = dx * dx + dy * dy + dz * dz;

            int hit;
            double best;
            if (tree != null) {
                hit = tree.closest(dx, dy, dz, a, nodeStack, entryStack, inverse, distance);
                best = distance[0];
            } else {
                hit = -1;
                best = Double.POSITIVE_INFINITY;
                for (int i = 0; i < scene.size; i++) {
                    if (!bounds.mayHit(i, x, y)) {
                        continue;
                    }
                    double s = scene.nearestRoot(i, dx, dy, dz, a);
                    if (s < best) {
                        best = s;
                        hit = i;
                    }
                }
            }
            hitDistance = best;
            hitDx = dx;
            hitDy = dy;
            hitDz = dz;
            return hit;
        }

        /** {@code Renderer.illuminate} at the hit s along D on sphere i, operation for operation. */
        private void shade(int i, double s, double dx, double dy, double dz) {
            FlatScene f = scene;
            // P = O + s D, N = normalise(P - C).
            double x = 0 + s * dx, y = 0 + s * dy, z = 0 + s * dz;
            double nx = x - f.cx[i], ny = y - f.cy[i], nz = z - f.cz[i];
            double nLength = Math.sqrt(nx * nx + ny * ny + nz * nz);
            nx = nx / nLength;
            ny = ny / nLength;
            nz = nz / nLength;

            double ambientRed = f.red[i] * f.ambientRed;
            double ambientGreen = f.green[i] * f.ambientGreen;
            double ambientBlue = f.blue[i] * f.ambientBlue;
            if (!f.lit) {
                red = ambientRed;
                green = ambientGreen;
                blue = ambientBlue;
                return;
            }
            double lx = f.lightX - x, ly = f.lightY - y, lz = f.lightZ - z;
            double distance = Math.sqrt(lx * lx + ly * ly + lz * lz);
            double falloff = f.intensity / (Math.PI * 4 * Math.pow(distance, 2));
            double iRed = falloff * f.lightRed, iGreen = falloff * f.lightGreen, iBlue = falloff * f.lightBlue;
            lx = lx / distance;
            ly = ly / distance;
            lz = lz / distance;
            double vx = -1 * x, vy = -1 * y, vz = -1 * z;
            double vLength = Math.sqrt(vx * vx + vy * vy + vz * vz);
            vx = vx / vLength;
            vy = vy / vLength;
            vz = vz / vLength;
            double twiceLdotN = 2 * (lx * nx + ly * ny + lz * nz);
            double rx = twiceLdotN * nx - lx, ry = twiceLdotN * ny - ly, rz = twiceLdotN * nz - lz;

            double NdotL = nx * lx + ny * ly + nz * lz;
            double RdotV = rx * vx + ry * vy + rz * vz;
            double diffuse = 0.8 * Math.max(0, NdotL);
            // pow(max(0, R.V), n) is 0 whenever R.V <= 0, as it is on most of a sphere: skip the
            // costly pow there (the same value; a NaN still goes through pow and stays NaN).
            double specular = RdotV <= 0 ? 0.8 * 0.0 : 0.8 * Math.pow(Math.max(0, RdotV), 10);

            red = ambientRed + diffuse * (f.red[i] * iRed) + specular * (1 * iRed);
            green = ambientGreen + diffuse * (f.green[i] * iGreen) + specular * (1 * iGreen);
            blue = ambientBlue + diffuse * (f.blue[i] * iBlue) + specular * (1 * iBlue);
        }
    }

    private static int toRGB(double red, double green, double blue) {
        return Vector3.toByte(red) << 16 | Vector3.toByte(green) << 8 | Vector3.toByte(blue);
    }
}
