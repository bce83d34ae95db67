package gfx.tick1.fast;

import gfx.tick1.render.ReferenceRenderer;
import gfx.tick1.render.SamplePattern;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.RobustIntersection;
import java.util.Arrays;

/**
 * The tracer for large frames, written so that the JIT vectorises it.
 *
 * <p>Each sample of a row is traced in passes over the whole row, each pass one step of the
 * readable code for every pixel: the camera's rays, their nearest hits, Phong's shading, and the
 * sums of the samples' colours. Every pass performs the readable code's floating-point
 * operations in the same order, so every value has the same bits.
 *
 * <h2>Why passes</h2>
 * A pixel's work is a chain of square roots and divisions, each waiting for the one before. In
 * a pass, neighbouring pixels' chains are independent, and the JIT (C2's superword optimisation)
 * turns a loop of plain arithmetic over arrays into vector instructions that work on four or
 * eight pixels at once. IEEE 754 rounds each vector lane exactly as it rounds a scalar, so this
 * changes no bit. Four rules keep a loop vectorisable on JDK 17, and explain the shape of the
 * code below:
 * <ul>
 * <li>a small body: C2 unrolls, and so vectorises, only loops of up to about 60 nodes (the
 *   flag LoopUnrollLimit), which is about six array accesses and a dozen operations; so each
 *   loop is one line of the maths, with its intermediate results in arrays;</li>
 * <li>no branches: a branch is taken per pixel afterwards, in a separate scalar loop;</li>
 * <li>no use of the loop counter as a number (JDK 17 cannot vectorise that): the pixel's
 *   column is read from {@link #column} instead;</li>
 * <li>no memory reads through a per-pixel index: the hit sphere's centre and colour are first
 *   gathered into arrays indexed by pixel.</li>
 * </ul>
 * Measured on one core at 3840 x 2160 on tick1.xml, the camera's pass went from 45 to 7 ms, the
 * shading from 70 to 25 ms, and the whole frame from 250 to 155 ms. What is left is mostly scalar:
 * the per-pixel decisions (keepNearer), Math.pow for the specular term, and the cast to bytes.
 *
 * <p>For each sphere only the pixels of its {@link ScreenBounds} rectangle are tested; for
 * scenes with many spheres, the {@link SphereBvh} chooses the spheres, one pixel at a time.
 */
final class VectorTracer implements Tracer {

    private final FlatScene scene;
    private final SphereBvh tree;
    private final ScreenBounds bounds;
    private final Frame frame;
    private final SamplePattern samples;
    private final int width;
    private final boolean handout, keepHandoutWhereAccurate;

    private final int[] nodeStack = new int[64];
    private final double[] entryStack = new double[64];
    private final double[] inverse = new double[3];
    private final double[] distance = new double[1];

    // One entry a pixel of the row, for the sample being traced.
    /** x as a double, for {@link Frame#rayDirections}. */
    private final double[] column;
    /** The ray's unit direction D, a = D.D and 1 / a. */
    private final double[] dx, dy, dz, a, overA;
    /** The nearest hit so far: the sphere's index (-1 for none) and s. */
    private final int[] hit;
    private final double[] s;
    /** One sphere's quadratic: beta = D.f, the handout's root of its discriminant and its two roots. */
    private final double[] beta, sqrtDiscriminant, handoutNear, handoutFar;
    /** The robust method's estimates (see {@link RobustIntersection#nearestRoot}). */
    private final double[] betaAbs, bound, roughDelta, sqrtLow, sensitivity, quickNear, quickFar, spread, largest, rootError;
    /** The hit sphere's centre and C_diff. */
    private final double[] centreX, centreY, centreZ, diffuseRed, diffuseGreen, diffuseBlue;
    /** The hit point P, the unit normal N, the unit directions to the light (L) and to the camera (V). */
    private final double[] pointX, pointY, pointZ, normalX, normalY, normalZ;
    private final double[] length, nDotL, lightDistance, toLightX, toLightY, toLightZ, toCameraX, toCameraY, toCameraZ;
    /** Ambient plus diffuse, the light's illumination I, R.V and the specular factor k_s max(0, R.V)^n. */
    private final double[] baseRed, baseGreen, baseBlue, iRed, iGreen, iBlue, rDotV, specular;
    /** The sum of the samples' colours so far, and room for the bytes, for {@link Tracer#packRow}. */
    private final double[] sumRed, sumGreen, sumBlue;
    private final double[][] bytes;

    VectorTracer(FlatScene scene, SphereBvh tree, ScreenBounds bounds, Frame frame) {
        this.scene = scene;
        this.tree = tree;
        this.bounds = bounds;
        this.frame = frame;
        this.samples = frame.samples();
        this.width = frame.width();
        handout = scene.intersection == Intersection.HANDOUT;
        keepHandoutWhereAccurate = scene.intersection == Intersection.ROBUST;
        column = frame.columns();
        bytes = new double[3][width];
        dx = new double[width];
        dy = new double[width];
        dz = new double[width];
        a = new double[width];
        overA = new double[width];
        hit = new int[width];
        s = new double[width];
        beta = new double[width];
        sqrtDiscriminant = new double[width];
        handoutNear = new double[width];
        handoutFar = new double[width];
        betaAbs = new double[width];
        bound = new double[width];
        roughDelta = new double[width];
        sqrtLow = new double[width];
        sensitivity = new double[width];
        quickNear = new double[width];
        quickFar = new double[width];
        spread = new double[width];
        largest = new double[width];
        rootError = new double[width];
        centreX = new double[width];
        centreY = new double[width];
        centreZ = new double[width];
        diffuseRed = new double[width];
        diffuseGreen = new double[width];
        diffuseBlue = new double[width];
        pointX = new double[width];
        pointY = new double[width];
        pointZ = new double[width];
        normalX = new double[width];
        normalY = new double[width];
        normalZ = new double[width];
        length = new double[width];
        nDotL = new double[width];
        lightDistance = new double[width];
        toLightX = new double[width];
        toLightY = new double[width];
        toLightZ = new double[width];
        toCameraX = new double[width];
        toCameraY = new double[width];
        toCameraZ = new double[width];
        baseRed = new double[width];
        baseGreen = new double[width];
        baseBlue = new double[width];
        iRed = new double[width];
        iGreen = new double[width];
        iBlue = new double[width];
        rDotV = new double[width];
        specular = new double[width];
        sumRed = new double[width];
        sumGreen = new double[width];
        sumBlue = new double[width];
    }

    @Override
    public void row(int y, int[] pixels, int offset) {
        for (int i = 0; i < samples.size(); i++) {
            double offsetX = samples.dx(i), sampleY = y + samples.dy(i);
            directions(offsetX, sampleY);
            nearestHits(offsetX, sampleY);
            shade();
            addColour(sumRed, baseRed, iRed, i == 0);
            addColour(sumGreen, baseGreen, iGreen, i == 0);
            addColour(sumBlue, baseBlue, iBlue, i == 0);
        }
        // The mean, as the readable code takes it: the sum scaled by 1 / N (exactly the sum for N = 1).
        Tracer.packRow(sumRed, sumGreen, sumBlue, 1.0 / samples.size(), bytes, pixels, offset);
    }

    /** The Camera's rays, and a = D.D and 1 / a for the quadratic. */
    private void directions(double offsetX, double sampleY) {
        frame.rayDirections(offsetX, sampleY, column, dx, dy, dz);
        for (int x = 0; x < width; x++) {
            a[x] = dx[x] * dx[x] + dy[x] * dy[x] + dz[x] * dz[x];
            overA[x] = 1 / a[x];
        }
    }

    /** The sphere each ray meets first (-1 for none) and at what distance. */
    private void nearestHits(double offsetX, double sampleY) {
        if (tree != null) {
            nearestHitsInTree();
            return;
        }
        Arrays.fill(hit, -1);
        Arrays.fill(s, Double.POSITIVE_INFINITY);
        // Sphere by sphere in file order, keeping a hit only when strictly nearer: ties go to the
        // earlier sphere, as in the readable code's loop over the scene.
        for (int i = 0; i < scene.size; i++) {
            if (!(sampleY >= bounds.top[i] && sampleY <= bounds.bottom[i])) {
                continue;
            }
            // Every x with x + offsetX inside [left, right], and perhaps one more at each end.
            int from = (int) Math.max(0, Math.floor(bounds.left[i] - offsetX));
            int to = (int) Math.min(width - 1, Math.ceil(bounds.right[i] - offsetX));
            if (from > to) {
                continue;
            }
            RobustIntersection.Offset offset = scene.offsets[i];
            // The handout's quadratic, term for term as Sphere.intersectionWith computes it.
            beta(offset, from, to);
            handoutRootOfDiscriminant(scene.c[i], from, to);
            handoutRoots(from, to);
            if (!handout) {
                // The robust method's estimates (RobustIntersection.nearestRoot), and its quick test
                // where the handout's root may be kept.
                betaAbs(offset, from, to);
                boundAndRoughDelta(offset, from, to);
                if (keepHandoutWhereAccurate) {
                    quickSquareRoot(from, to);
                    quickRoots(from, to);
                    quickSpread(from, to);
                    quickLargest(from, to);
                    quickRootError(from, to);
                }
            }
            keepNearer(i, offset, from, to);
        }
    }

    /** With a BVH, one ray at a time. */
    private void nearestHitsInTree() {
        for (int x = 0; x < width; x++) {
            hit[x] = tree.closest(dx[x], dy[x], dz[x], a[x], nodeStack, entryStack, inverse, distance);
            s[x] = distance[0];
        }
    }

    /** beta = D.f with f = O - C: half the handout's b, which is 2 beta exactly. */
    private void beta(RobustIntersection.Offset offset, int from, int to) {
        for (int x = from; x <= to; x++) {
            beta[x] = RobustIntersection.roughBeta(dx[x], dy[x], dz[x], offset);
        }
    }

    /** The square root of the handout's discriminant b^2 - 4ac: NaN when it is negative, which keepNearer takes as a miss. */
    private void handoutRootOfDiscriminant(double c, int from, int to) {
        for (int x = from; x <= to; x++) {
            double b = 2 * beta[x];
            sqrtDiscriminant[x] = Math.sqrt(b * b - 4 * a[x] * c);
        }
    }

    /** The handout's roots (-b -+ root) / 2a. */
    private void handoutRoots(int from, int to) {
        for (int x = from; x <= to; x++) {
            double b = 2 * beta[x];
            handoutNear[x] = (-b - sqrtDiscriminant[x]) / (2 * a[x]);
            handoutFar[x] = (-b + sqrtDiscriminant[x]) / (2 * a[x]);
        }
    }

    private void betaAbs(RobustIntersection.Offset offset, int from, int to) {
        for (int x = from; x <= to; x++) {
            betaAbs[x] = RobustIntersection.betaAbs(dx[x], dy[x], dz[x], offset);
        }
    }

    private void boundAndRoughDelta(RobustIntersection.Offset offset, int from, int to) {
        for (int x = from; x <= to; x++) {
            bound[x] = RobustIntersection.discriminantBound(a[x], betaAbs[x], offset);
            roughDelta[x] = RobustIntersection.roughDelta(a[x], beta[x], offset);
        }
    }

    private void quickSquareRoot(int from, int to) {
        for (int x = from; x <= to; x++) {
            double low = RobustIntersection.quickSquareRoot(roughDelta[x], bound[x]);
            sqrtLow[x] = low;
            sensitivity[x] = bound[x] * (1 / low);
        }
    }

    private void quickRoots(int from, int to) {
        for (int x = from; x <= to; x++) {
            quickNear[x] = RobustIntersection.quickNear(beta[x], sqrtLow[x], overA[x]);
            quickFar[x] = RobustIntersection.quickFar(beta[x], sqrtLow[x], overA[x]);
        }
    }

    private void quickSpread(int from, int to) {
        for (int x = from; x <= to; x++) {
            spread[x] = RobustIntersection.quickSpread(betaAbs[x], sensitivity[x], overA[x], quickNear[x], quickFar[x]);
        }
    }

    private void quickLargest(int from, int to) {
        for (int x = from; x <= to; x++) {
            largest[x] = RobustIntersection.quickLargest(quickNear[x], quickFar[x], spread[x]);
        }
    }

    private void quickRootError(int from, int to) {
        for (int x = from; x <= to; x++) {
            rootError[x] = RobustIntersection.quickRootError(betaAbs[x], sensitivity[x], sqrtLow[x], overA[x], largest[x]);
        }
    }

    /**
     * Takes sphere i's nearest root s &gt; 0 where it is nearer than the hit so far: the handout's
     * root, or for the robust methods {@link RobustIntersection#nearestRoot}'s decision from the
     * estimates (which keeps the handout's root wherever that is provably accurate).
     */
    private void keepNearer(int i, RobustIntersection.Offset offset, int from, int to) {
        for (int x = from; x <= to; x++) {
            double root;
            if (!handout) {
                root = RobustIntersection.nearestRoot(dx[x], dy[x], dz[x], a[x], offset, keepHandoutWhereAccurate,
                        betaAbs[x], bound[x], roughDelta[x], quickNear[x], quickFar[x], spread[x], rootError[x]);
                if (root == RobustIntersection.HANDOUT_IS_ACCURATE) {
                    root = handoutNear[x] > 0 ? handoutNear[x] : handoutFar[x];
                }
            } else {
                root = handoutNear[x] > 0 ? handoutNear[x] : handoutFar[x];
            }
            if (root > 0 && root < s[x]) {
                s[x] = root;
                hit[x] = i;
            }
        }
    }

    /**
     * {@code Renderer.illuminate} at every hit, operation for operation, into the arrays that
     * addColour sums: Phong's model for the pixels in [first, last], the span with hits, where
     * a miss computes nonsense from s = infinity that the last loop replaces.
     */
    private void shade() {
        int first = 0, last = width - 1;
        while (first <= last && hit[first] < 0) {
            first++;
        }
        while (last >= first && hit[last] < 0) {
            last--;
        }
        gatherHitSpheres(first, last);
        if (scene.lit) {
            shadeLit(first, last);
        } else {
            ambientOnly(first, last);
        }
        // Outside [first, last] every ray missed.
        background(0, first);
        background(last + 1, width);
        missesAndSpecular(first, last);
    }

    /** Each pixel's hit sphere's centre and colour (sphere 0's for a miss, to be overwritten). */
    private void gatherHitSpheres(int first, int last) {
        for (int p = first; p <= last; p++) {
            int i = Math.max(0, hit[p]);
            centreX[p] = scene.cx[i];
            centreY[p] = scene.cy[i];
            centreZ[p] = scene.cz[i];
            diffuseRed[p] = scene.red[i];
            diffuseGreen[p] = scene.green[i];
            diffuseBlue[p] = scene.blue[i];
        }
    }

    /**
     * Phong's model under the point light, all of it but the specular power. One short loop per
     * line of the maths, each its own method: C2 vectorises a loop only while its body is small,
     * and compiles a method once for each of its hot loops (on-stack replacement), so a method
     * with many loops would cost it far more.
     */
    private void shadeLit(int first, int last) {
        hitPoints(first, last);
        // N = normalise(P - C).
        difference(normalX, normalY, normalZ, pointX, pointY, pointZ, centreX, centreY, centreZ, first, last);
        lengths(normalX, normalY, normalZ, length, first, last);
        divide(normalX, normalY, normalZ, length, first, last);
        // L = normalise(light - P), keeping the distance to the light.
        towardsLight(first, last);
        lengths(toLightX, toLightY, toLightZ, lightDistance, first, last);
        divide(toLightX, toLightY, toLightZ, lightDistance, first, last);
        illumination(first, last);
        // V = normalise(-P): towards the camera at the origin.
        towardsCamera(first, last);
        lengths(toCameraX, toCameraY, toCameraZ, length, first, last);
        divide(toCameraX, toCameraY, toCameraZ, length, first, last);
        // N.L, then R = 2 (L.N) N - L (L mirrored in N; L.N is N.L with the products swapped), then R.V.
        nDotL(first, last);
        rDotVxy(first, last);
        rDotVz(first, last);
        // Ambient plus diffuse: C_diff I_a + C_diff I k_d max(0, N.L).
        ambientPlusDiffuse(baseRed, diffuseRed, iRed, scene.ambientRed, first, last);
        ambientPlusDiffuse(baseGreen, diffuseGreen, iGreen, scene.ambientGreen, first, last);
        ambientPlusDiffuse(baseBlue, diffuseBlue, iBlue, scene.ambientBlue, first, last);
    }

    /** P = O + s D, with O = 0. */
    private void hitPoints(int first, int last) {
        for (int p = first; p <= last; p++) {
            pointX[p] = 0 + s[p] * dx[p];
            pointY[p] = 0 + s[p] * dy[p];
            pointZ[p] = 0 + s[p] * dz[p];
        }
    }

    /** (x, y, z) = (ax, ay, az) - (bx, by, bz). */
    private static void difference(double[] x, double[] y, double[] z, double[] ax, double[] ay, double[] az,
            double[] bx, double[] by, double[] bz, int first, int last) {
        for (int p = first; p <= last; p++) {
            x[p] = ax[p] - bx[p];
            y[p] = ay[p] - by[p];
            z[p] = az[p] - bz[p];
        }
    }

    /** The lengths sqrt(x^2 + y^2 + z^2), as Vector3.magnitude computes them. */
    private static void lengths(double[] x, double[] y, double[] z, double[] length, int first, int last) {
        for (int p = first; p <= last; p++) {
            length[p] = Math.sqrt(x[p] * x[p] + y[p] * y[p] + z[p] * z[p]);
        }
    }

    /** Each component divided by its length: with {@link #lengths}, Vector3.normalised. */
    private static void divide(double[] x, double[] y, double[] z, double[] length, int first, int last) {
        for (int p = first; p <= last; p++) {
            x[p] = x[p] / length[p];
            y[p] = y[p] / length[p];
            z[p] = z[p] / length[p];
        }
    }

    /** light - P. */
    private void towardsLight(int first, int last) {
        double lightX = scene.lightX, lightY = scene.lightY, lightZ = scene.lightZ;
        for (int p = first; p <= last; p++) {
            toLightX[p] = lightX - pointX[p];
            toLightY[p] = lightY - pointY[p];
            toLightZ[p] = lightZ - pointZ[p];
        }
    }

    /** I = colour intensity / (4 pi d^2): PointLight.getIlluminationAt. */
    private void illumination(int first, int last) {
        double intensity = scene.intensity;
        double lightRed = scene.lightRed, lightGreen = scene.lightGreen, lightBlue = scene.lightBlue;
        for (int p = first; p <= last; p++) {
            double falloff = intensity / (Math.PI * 4 * Math.pow(lightDistance[p], 2));
            iRed[p] = falloff * lightRed;
            iGreen[p] = falloff * lightGreen;
            iBlue[p] = falloff * lightBlue;
        }
    }

    /** -1 P: P.scale(-1). */
    private void towardsCamera(int first, int last) {
        for (int p = first; p <= last; p++) {
            toCameraX[p] = -1 * pointX[p];
            toCameraY[p] = -1 * pointY[p];
            toCameraZ[p] = -1 * pointZ[p];
        }
    }

    private void nDotL(int first, int last) {
        for (int p = first; p <= last; p++) {
            nDotL[p] = normalX[p] * toLightX[p] + normalY[p] * toLightY[p] + normalZ[p] * toLightZ[p];
        }
    }

    /** The first two terms of R.V, R_x V_x + R_y V_y ... */
    private void rDotVxy(int first, int last) {
        for (int p = first; p <= last; p++) {
            double twiceLdotN = 2 * nDotL[p];
            rDotV[p] = (twiceLdotN * normalX[p] - toLightX[p]) * toCameraX[p]
                    + (twiceLdotN * normalY[p] - toLightY[p]) * toCameraY[p];
        }
    }

    /** ... plus the third, R_z V_z. */
    private void rDotVz(int first, int last) {
        for (int p = first; p <= last; p++) {
            rDotV[p] = rDotV[p] + (2 * nDotL[p] * normalZ[p] - toLightZ[p]) * toCameraZ[p];
        }
    }

    /** One channel of ambient plus diffuse light. */
    private void ambientPlusDiffuse(double[] base, double[] C_diff, double[] I, double I_a, int first, int last) {
        for (int p = first; p <= last; p++) {
            base[p] = C_diff[p] * I_a + 0.8 * Math.max(0, nDotL[p]) * (C_diff[p] * I[p]);
        }
    }

    /** Without a point light, C_diff I_a alone. */
    private void ambientOnly(int first, int last) {
        for (int p = first; p <= last; p++) {
            baseRed[p] = diffuseRed[p] * scene.ambientRed;
            baseGreen[p] = diffuseGreen[p] * scene.ambientGreen;
            baseBlue[p] = diffuseBlue[p] * scene.ambientBlue;
        }
    }

    /** The background for the misses in [first, last]; the specular factor for the hits. */
    private void missesAndSpecular(int first, int last) {
        for (int p = first; p <= last; p++) {
            if (hit[p] < 0) {
                baseRed[p] = ReferenceRenderer.BACKGROUND_COLOUR.x;
                baseGreen[p] = ReferenceRenderer.BACKGROUND_COLOUR.y;
                baseBlue[p] = ReferenceRenderer.BACKGROUND_COLOUR.z;
                iRed[p] = iGreen[p] = iBlue[p] = 0;
                specular[p] = 0;
            } else if (!scene.lit) {
                iRed[p] = iGreen[p] = iBlue[p] = 0;
                specular[p] = 0;
            } else {
                // pow(max(0, R.V), n) is 0 whenever R.V <= 0, as on half the hits (49% on tick1.xml):
                // skip the costly pow there (the same value; a NaN still goes through pow).
                double RdotV = rDotV[p];
                specular[p] = RdotV <= 0 ? 0.8 * 0.0 : 0.8 * Math.pow(Math.max(0, RdotV), 10);
            }
        }
    }

    /** The background for pixels [from, to), as base + specular I with both of the last zero. */
    private void background(int from, int to) {
        Arrays.fill(baseRed, from, to, ReferenceRenderer.BACKGROUND_COLOUR.x);
        Arrays.fill(baseGreen, from, to, ReferenceRenderer.BACKGROUND_COLOUR.y);
        Arrays.fill(baseBlue, from, to, ReferenceRenderer.BACKGROUND_COLOUR.z);
        Arrays.fill(iRed, from, to, 0);
        Arrays.fill(iGreen, from, to, 0);
        Arrays.fill(iBlue, from, to, 0);
        Arrays.fill(specular, from, to, 0);
    }

    /**
     * Adds one channel of each pixel's colour for this sample, base + specular (C_spec I) with
     * C_spec = 1, to its sum. For a miss or an unlit scene the last term is 0 * 0.
     */
    private void addColour(double[] sum, double[] base, double[] I, boolean first) {
        if (first) {
            for (int p = 0; p < width; p++) {
                sum[p] = base[p] + specular[p] * (1 * I[p]);
            }
        } else {
            for (int p = 0; p < width; p++) {
                sum[p] = sum[p] + (base[p] + specular[p] * (1 * I[p]));
            }
        }
    }
}
