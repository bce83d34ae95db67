package gfx.tick1.render;

import gfx.tick1.math.Ray;
import gfx.tick1.math.Vector3;
import gfx.tick1.scene.Intersection;
import gfx.tick1.scene.PointLight;
import gfx.tick1.scene.RaycastHit;
import gfx.tick1.scene.Scene;
import gfx.tick1.scene.Sphere;
import java.awt.image.BufferedImage;
import java.util.stream.IntStream;

/** Traces one ray per pixel and shades hits with the Phong model (handout section 5). */
public class Renderer {

    /** The colour of a ray that hits nothing: 0.1 grey, which truncates to 25 per channel. */
    public static final Vector3 BACKGROUND_COLOUR = new Vector3(0.1);

    private final int width, height;
    private final Intersection intersection;

    public Renderer(int width, int height) {
        this(width, height, Intersection.DEFAULT);
    }

    /** A renderer that intersects rays with spheres by the given method. */
    public Renderer(int width, int height, Intersection intersection) {
        this.width = width;
        this.height = height;
        this.intersection = intersection;
    }

    /** The colour seen along a ray: the Phong shade of the nearest hit, or the background. */
    protected Vector3 trace(Scene scene, Ray ray) {
        RaycastHit closestHit = scene.findClosestIntersection(ray, intersection);
        Sphere objectHit = closestHit.getObjectHit();
        if (objectHit == null) {
            return BACKGROUND_COLOUR;
        }
        return illuminate(scene, objectHit, closestHit.getLocation(), closestHit.getNormal());
    }

    /**
     * Phong's model at the point P with unit normal N:
     * C_diff I_a + C_diff k_d I max(0, N.L) + C_spec k_s I max(0, R.V)^n, where * between
     * colours is per channel, L and V are the unit directions to the light and to the camera,
     * and R is L mirrored in N.
     */
    private Vector3 illuminate(Scene scene, Sphere object, Vector3 P, Vector3 N) {
        Vector3 I_a = scene.getAmbientLighting();
        Vector3 C_diff = object.getColour();
        Vector3 ambient = C_diff.scale(I_a);

        PointLight light = scene.getPointLight();
        if (light == null) {
            return ambient;
        }
        double distanceToLight = light.getPosition().subtract(P).magnitude();
        Vector3 I = light.getIlluminationAt(distanceToLight);
        Vector3 C_spec = new Vector3(1);

        double k_d = object.getPhong_kD();
        double k_s = object.getPhong_kS();
        double n = object.getPhong_n();

        Vector3 L = light.getPosition().subtract(P).normalised();
        Vector3 V = P.scale(-1).normalised(); // the camera is at the origin
        Vector3 R = L.reflectIn(N);

        double NdotL = N.dot(L);
        double RdotV = R.dot(V);

        Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, NdotL));
        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, RdotV), n));

        return ambient.add(diffuse).add(specular);
    }

    /** Renders the scene on all cores; each pixel is computed alone, so the image is the same. */
    public BufferedImage render(Scene scene) {
        return render(scene, new SamplePattern(1));
    }

    /**
     * Renders the scene, rows shared among the cores. With one sample, one {@code castRay} per
     * pixel through its centre; with more, the average of the samples' colours, taken before
     * the conversion to bytes.
     */
    public BufferedImage render(Scene scene, SamplePattern samples) {
        Camera camera = new Camera(width, height);
        int[] pixels = new int[width * height];
        IntStream.range(0, height).parallel().forEach(y -> {
            for (int x = 0; x < width; x++) {
                pixels[y * width + x] = pixel(scene, camera, samples, x, y).toRGB();
            }
        });
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, pixels, 0, width);
        return image;
    }

    /** The mean colour of the pixel's samples; one sample is exactly the ray through its centre. */
    private Vector3 pixel(Scene scene, Camera camera, SamplePattern samples, int x, int y) {
        Vector3 sum = trace(scene, camera.castRay(x + samples.dx(0), y + samples.dy(0)));
        for (int i = 1; i < samples.size(); i++) {
            sum = sum.add(trace(scene, camera.castRay(x + samples.dx(i), y + samples.dy(i))));
        }
        return sum.scale(1.0 / samples.size());
    }
}
