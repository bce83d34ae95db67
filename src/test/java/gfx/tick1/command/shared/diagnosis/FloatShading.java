package gfx.tick1.command.shared.diagnosis;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.Camera;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import java.awt.image.BufferedImage;

/**
 * The correct code with illuminate's arithmetic in float: the Phong sum of the handout's
 * section 5, C_diff I_a + C_diff k_d I max(0, N.L) + k_s I max(0, R.V)^n, every quantity a float.
 * The intersection stays the reference's, so the outlines are the correct ones.
 */
public final class FloatShading {

    private FloatShading() {
    }

    public static BufferedImage render(Scene scene, int width, int height) {
        Camera camera = new Camera(width, height);
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                RaycastHit hit = scene.findClosestIntersection(camera.castRay(x, y));
                Vector3 colour = hit.getObjectHit() == null ? new Vector3(0.1) : shade(scene, hit);
                image.setRGB(x, y, colour.toRGB());
            }
        }
        return image;
    }

    private static Vector3 shade(Scene scene, RaycastHit hit) {
        Sphere object = hit.getObjectHit();
        PointLight light = scene.getPointLight();
        float[] p = floats(hit.getLocation()), n = floats(hit.getNormal());
        float[] toLight = minus(floats(light.getPosition()), p);
        float distance = (float) Math.sqrt(dot(toLight, toLight));
        float[] l = times(toLight, 1 / distance), v = times(p, -1 / (float) Math.sqrt(dot(p, p)));
        float nDotL = dot(n, l);
        float[] r = minus(times(n, 2 * nDotL), l);
        float fallOff = (float) light.getIntensity() / ((float) Math.PI * 4 * distance * distance);
        float diffuse = (float) object.getPhong_kD() * Math.max(0, nDotL);
        float specular = (float) object.getPhong_kS() * (float) Math.pow(Math.max(0, dot(r, v)), object.getPhong_n());
        float[] cDiff = floats(object.getColour()), iA = floats(scene.getAmbientLighting());
        float[] lightColour = floats(light.getColour());
        float[] sum = new float[3];
        for (int i = 0; i < 3; i++) {
            float intensity = lightColour[i] * fallOff;
            sum[i] = cDiff[i] * iA[i] + cDiff[i] * intensity * diffuse + intensity * specular;
        }
        return new Vector3(sum[0], sum[1], sum[2]);
    }

    private static float[] floats(Vector3 v) {
        return new float[] {(float) v.x, (float) v.y, (float) v.z};
    }

    private static float[] minus(float[] a, float[] b) {
        return new float[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static float[] times(float[] a, float s) {
        return new float[] {a[0] * s, a[1] * s, a[2] * s};
    }

    private static float dot(float[] a, float[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
}
