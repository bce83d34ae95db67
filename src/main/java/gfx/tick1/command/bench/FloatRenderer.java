package gfx.tick1.command.bench;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.stream.IntStream;

/**
 * The whole pipeline in single precision, for the benchmark's question "what would float cost
 * in accuracy, and buy in speed?". It is the fast kernel's structure with every quantity a
 * float: the camera, the intersection and the Phong shading. It is not used to make images.
 */
final class FloatRenderer {

    /** Which quadratic formula to use for s. */
    enum Formula {
        /** s = (-b -+ sqrt(b^2 - 4ac)) / 2a, as the handout writes it. */
        HANDOUT,
        /**
         * The geometric quarter discriminant a r^2 - |D x f|^2 and the stable roots c / q and
         * q / a with q = -(beta + sign(beta) sqrt(Delta)) (Ray Tracing Gems, ch. 7).
         */
        ROBUST
    }

    private final int width, height;
    private final Formula formula;

    FloatRenderer(int width, int height, Formula formula) {
        this.width = width;
        this.height = height;
        this.formula = formula;
    }

    BufferedImage render(Scene scene) {
        List<Sphere> spheres = scene.getObjects();
        int n = spheres.size();
        float[] cx = new float[n], cy = new float[n], cz = new float[n], rr = new float[n];
        float[] red = new float[n], green = new float[n], blue = new float[n];
        for (int i = 0; i < n; i++) {
            Sphere s = spheres.get(i);
            cx[i] = (float) SphereGeometry.centre(s).x;
            cy[i] = (float) SphereGeometry.centre(s).y;
            cz[i] = (float) SphereGeometry.centre(s).z;
            float r = (float) SphereGeometry.radius(s);
            rr[i] = r * r;
            red[i] = (float) s.getColour().x;
            green[i] = (float) s.getColour().y;
            blue[i] = (float) s.getColour().z;
        }
        Vector3 ambient = scene.getAmbientLighting();
        PointLight light = scene.getPointLight();
        float widthM = (float) (2 * Math.tan(Math.toRadians(45) / 2));
        float heightM = widthM / ((float) width / height);
        float xStep = widthM / width, yStep = heightM / height;
        int[] pixels = new int[width * height];
        IntStream.range(0, height).parallel().forEach(y -> {
            for (int x = 0; x < width; x++) {
                float px = (xStep - widthM) / 2 + x * xStep, py = (yStep + heightM) / 2 - y * yStep;
                float length = (float) Math.sqrt(px * px + py * py + 1);
                float dx = px / length, dy = py / length, dz = 1 / length;
                float best = Float.POSITIVE_INFINITY;
                int hit = -1;
                for (int i = 0; i < n; i++) {
                    float s = formula == Formula.HANDOUT ? handout(dx, dy, dz, -cx[i], -cy[i], -cz[i], rr[i])
                            : robust(dx, dy, dz, -cx[i], -cy[i], -cz[i], rr[i]);
                    if (s < best) {
                        best = s;
                        hit = i;
                    }
                }
                pixels[y * width + x] = hit < 0 ? 0x191919
                        : shade(best * dx, best * dy, best * dz, cx[hit], cy[hit], cz[hit],
                                red[hit], green[hit], blue[hit], ambient, light);
            }
        });
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, pixels, 0, width);
        return image;
    }

    private static float handout(float dx, float dy, float dz, float fx, float fy, float fz, float rr) {
        float a = dx * dx + dy * dy + dz * dz;
        float b = 2 * (dx * fx + dy * fy + dz * fz);
        float c = fx * fx + fy * fy + fz * fz - rr;
        float discriminant = b * b - 4 * a * c;
        if (discriminant < 0) {
            return Float.POSITIVE_INFINITY;
        }
        float root = (float) Math.sqrt(discriminant);
        float s1 = (-b - root) / (2 * a), s2 = (-b + root) / (2 * a);
        float s = s1 > 0 ? s1 : s2;
        return s > 0 ? s : Float.POSITIVE_INFINITY;
    }

    private static float robust(float dx, float dy, float dz, float fx, float fy, float fz, float rr) {
        float a = dx * dx + dy * dy + dz * dz;
        float beta = dx * fx + dy * fy + dz * fz;
        float wx = dy * fz - dz * fy, wy = dz * fx - dx * fz, wz = dx * fy - dy * fx;
        float delta = a * rr - (wx * wx + wy * wy + wz * wz);
        if (delta < 0) {
            return Float.POSITIVE_INFINITY;
        }
        float c = fx * fx + fy * fy + fz * fz - rr;
        float q = -(beta + Math.copySign((float) Math.sqrt(delta), beta));
        if (q == 0) {
            return Float.POSITIVE_INFINITY;
        }
        float t0 = c / q, t1 = q / a;
        float near = Math.min(t0, t1), far = Math.max(t0, t1);
        float s = near > 0 ? near : far;
        return s > 0 ? s : Float.POSITIVE_INFINITY;
    }

    private static int shade(float x, float y, float z, float cx, float cy, float cz,
            float red, float green, float blue, Vector3 ambient, PointLight light) {
        float ar = red * (float) ambient.x, ag = green * (float) ambient.y, ab = blue * (float) ambient.z;
        if (light == null) {
            return rgb(ar, ag, ab);
        }
        float nx = x - cx, ny = y - cy, nz = z - cz;
        float nLength = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
        nx /= nLength;
        ny /= nLength;
        nz /= nLength;
        float lx = (float) light.getPosition().x - x, ly = (float) light.getPosition().y - y,
                lz = (float) light.getPosition().z - z;
        float distance = (float) Math.sqrt(lx * lx + ly * ly + lz * lz);
        float falloff = (float) light.getIntensity() / (float) (Math.PI * 4) / (distance * distance);
        lx /= distance;
        ly /= distance;
        lz /= distance;
        float vLength = (float) Math.sqrt(x * x + y * y + z * z);
        float vx = -x / vLength, vy = -y / vLength, vz = -z / vLength;
        float nDotL = nx * lx + ny * ly + nz * lz;
        float rx = 2 * nDotL * nx - lx, ry = 2 * nDotL * ny - ly, rz = 2 * nDotL * nz - lz;
        float rDotV = rx * vx + ry * vy + rz * vz;
        float diffuse = 0.8f * Math.max(0, nDotL), specular = 0.8f * (float) Math.pow(Math.max(0, rDotV), 10);
        float ir = falloff * (float) light.getColour().x, ig = falloff * (float) light.getColour().y,
                ib = falloff * (float) light.getColour().z;
        return rgb(ar + diffuse * red * ir + specular * ir, ag + diffuse * green * ig + specular * ig,
                ab + diffuse * blue * ib + specular * ib);
    }

    private static int rgb(float r, float g, float b) {
        return Vector3.toByte(r) << 16 | Vector3.toByte(g) << 8 | Vector3.toByte(b);
    }
}
