package gfx.tick1.engine.fast;

import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.render.SamplePattern;

/**
 * One thread's tracing state, the fast renderer's kernel: each thread has its own, with its row
 * buffers, and traces whole rows with it.
 *
 * <p>A row is traced one sample at a time, in four passes over the whole row: the rays'
 * directions, their nearest hits, the shading up to R.V, and the specular term; each pixel's
 * colours are summed in sample order, as the readable code sums them. A pixel's work is one long
 * chain of dependent divisions and square roots; in passes, the chains of neighbouring pixels
 * are independent and the processor overlaps them. Two of its loops are written so that C2 turns
 * them into vector instructions: the camera's ({@link Frame#rayDirections}) and the conversion
 * to bytes ({@link #packRow}).
 *
 * <p>Why not more passes. Split into about thirty one-line passes, every one of which C2 turns
 * into vector instructions, a row is faster once the JIT has compiled it; but compiling those
 * loops costs more than they save in one run of tick1, which is how it renders. The measurements
 * behind both choices are in docs/benchmark.md, "How the default renderer is fast".
 */
final class Tracer {

    private final FlatScene scene;
    private final SphereBvh tree;
    private final ScreenBounds bounds;
    private final int[] nodeStack = new int[64];
    private final double[] entryStack = new double[64];
    private final double[] inverse = new double[3];
    private final double[] distance = new double[1];

    // One entry a pixel of the row, for the sample being traced.
    private final double[] dx, dy, dz;
    private final int[] hit;
    private final double[] s;
    /** Ambient plus diffuse, the light's illumination I, and R.V: all of Phong but the specular term. */
    private final double[] baseRed, baseGreen, baseBlue;
    private final double[] iRed, iGreen, iBlue;
    private final double[] rDotV;
    /** The sum of the samples' colours so far. */
    private final double[] sumRed, sumGreen, sumBlue;

    private final Frame frame;
    /** x as a double, for {@link Frame#rayDirections}; room for the bytes of a row, for {@link #packRow}. */
    private final double[] column;
    private final double[][] bytes;
    private final SamplePattern samples;
    private final int width;

    Tracer(FlatScene scene, SphereBvh tree, ScreenBounds bounds, Frame frame) {
        this.scene = scene;
        this.tree = tree;
        this.bounds = bounds;
        this.frame = frame;
        this.samples = frame.samples();
        this.width = frame.width();
        column = frame.columns();
        bytes = new double[3][width];
        dx = new double[width];
        dy = new double[width];
        dz = new double[width];
        hit = new int[width];
        s = new double[width];
        baseRed = new double[width];
        baseGreen = new double[width];
        baseBlue = new double[width];
        iRed = new double[width];
        iGreen = new double[width];
        iBlue = new double[width];
        rDotV = new double[width];
        sumRed = new double[width];
        sumGreen = new double[width];
        sumBlue = new double[width];
    }

    /** Traces row y into {@code pixels} from {@code offset} on, as packed 0xRRGGBB. */
    void row(int y, int[] pixels, int offset) {
        for (int i = 0; i < samples.size(); i++) {
            double offsetX = samples.dx(i), sampleY = y + samples.dy(i);
            frame.rayDirections(offsetX, sampleY, column, dx, dy, dz);
            nearestHits(offsetX, sampleY);
            shadeAllButSpecular();
            addColours(i == 0);
        }
        // The mean, as the readable code takes it: the sum scaled by 1 / N (exactly the sum for N = 1).
        packRow(sumRed, sumGreen, sumBlue, 1.0 / samples.size(), bytes, pixels, offset);
    }

    /** The sphere each ray meets first (-1 for none) and at what distance. */
    private void nearestHits(double offsetX, double sampleY) {
        for (int x = 0; x < width; x++) {
            double a = dx[x] * dx[x] + dy[x] * dy[x] + dz[x] * dz[x];
            if (tree != null) {
                hit[x] = tree.closest(dx[x], dy[x], dz[x], a, nodeStack, entryStack, inverse, distance);
                s[x] = distance[0];
                continue;
            }
            int nearest = -1;
            double best = Double.POSITIVE_INFINITY;
            for (int i = 0; i < scene.size; i++) {
                if (!bounds.mayHit(i, x + offsetX, sampleY)) {
                    continue;
                }
                double root = scene.nearestRoot(i, dx[x], dy[x], dz[x], a);
                if (root < best) {
                    best = root;
                    nearest = i;
                }
            }
            hit[x] = nearest;
            s[x] = best;
        }
    }

    /** {@code Renderer.illuminate} at every hit, operation for operation, up to the specular term. */
    private void shadeAllButSpecular() {
        FlatScene f = scene;
        for (int p = 0; p < width; p++) {
            int i = hit[p];
            if (i < 0) {
                continue;
            }
            // P = O + s D, N = normalise(P - C).
            double x = 0 + s[p] * dx[p], y = 0 + s[p] * dy[p], z = 0 + s[p] * dz[p];
            double nx = x - f.cx[i], ny = y - f.cy[i], nz = z - f.cz[i];
            double nLength = Math.sqrt(nx * nx + ny * ny + nz * nz);
            nx = nx / nLength;
            ny = ny / nLength;
            nz = nz / nLength;

            double ambientRed = f.red[i] * f.ambientRed;
            double ambientGreen = f.green[i] * f.ambientGreen;
            double ambientBlue = f.blue[i] * f.ambientBlue;
            if (!f.lit) {
                baseRed[p] = ambientRed;
                baseGreen[p] = ambientGreen;
                baseBlue[p] = ambientBlue;
                continue;
            }
            double lx = f.lightX - x, ly = f.lightY - y, lz = f.lightZ - z;
            double distance = Math.sqrt(lx * lx + ly * ly + lz * lz);
            double falloff = f.intensity / (Math.PI * 4 * Math.pow(distance, 2));
            double red = falloff * f.lightRed, green = falloff * f.lightGreen, blue = falloff * f.lightBlue;
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
            double diffuse = f.kD[i] * Math.max(0, NdotL);
            baseRed[p] = ambientRed + diffuse * (f.red[i] * red);
            baseGreen[p] = ambientGreen + diffuse * (f.green[i] * green);
            baseBlue[p] = ambientBlue + diffuse * (f.blue[i] * blue);
            iRed[p] = red;
            iGreen[p] = green;
            iBlue[p] = blue;
            rDotV[p] = rx * vx + ry * vy + rz * vz;
        }
    }

    /** Adds the specular term and each pixel's colour for this sample (the background for a miss) to its sum. */
    private void addColours(boolean first) {
        for (int p = 0; p < width; p++) {
            double red, green, blue;
            if (hit[p] < 0) {
                red = ReferenceRenderer.BACKGROUND_COLOUR.x;
                green = ReferenceRenderer.BACKGROUND_COLOUR.y;
                blue = ReferenceRenderer.BACKGROUND_COLOUR.z;
            } else if (!scene.lit) {
                red = baseRed[p];
                green = baseGreen[p];
                blue = baseBlue[p];
            } else {
                // pow(max(0, R.V), n) is 0 whenever R.V <= 0, as on half the hits (49% on tick1.xml):
                // skip the costly pow there (the same value; a NaN still goes through pow).
                int i = hit[p];
                double RdotV = rDotV[p];
                double k_s = scene.kS[i];
                double specular = RdotV <= 0 ? k_s * 0.0 : k_s * Math.pow(Math.max(0, RdotV), scene.n[i]);
                red = baseRed[p] + specular * (1 * iRed[p]);
                green = baseGreen[p] + specular * (1 * iGreen[p]);
                blue = baseBlue[p] + specular * (1 * iBlue[p]);
            }
            sumRed[p] = first ? red : sumRed[p] + red;
            sumGreen[p] = first ? green : sumGreen[p] + green;
            sumBlue[p] = first ? blue : sumBlue[p] + blue;
        }
    }

    /**
     * Packs a row's colours, the sums of its samples' colours scaled by {@code scale}, as
     * 0xRRGGBB into {@code pixels} from {@code offset} on: {@code Vector3.toByte} per channel, in
     * two steps, the clamped channel times 255 in doubles ({@code bytes}, three arrays of the
     * row's width to work in), then the cast to int. The first step vectorises; in one loop
     * with the cast, Math.min and Math.max would run a pixel at a time.
     */
    private static void packRow(double[] red, double[] green, double[] blue, double scale, double[][] bytes,
            int[] pixels, int offset) {
        clampedChannel(bytes[0], red, scale);
        clampedChannel(bytes[1], green, scale);
        clampedChannel(bytes[2], blue, scale);
        double[] byteRed = bytes[0], byteGreen = bytes[1], byteBlue = bytes[2];
        for (int x = 0; x < byteRed.length; x++) {
            pixels[offset + x] = (int) byteRed[x] << 16 | (int) byteGreen[x] << 8 | (int) byteBlue[x];
        }
    }

    /** 255 max(0, min(1, scale * sum)): Vector3.toByte before its cast. */
    private static void clampedChannel(double[] into, double[] sum, double scale) {
        for (int x = 0; x < into.length; x++) {
            into[x] = 255 * Math.max(0, Math.min(1, scale * sum[x]));
        }
    }
}
