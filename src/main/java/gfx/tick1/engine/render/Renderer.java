package gfx.tick1.engine.render;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import java.awt.image.BufferedImage;

public class Renderer {

    // What a ray that meets no sphere sees: 0.1 grey, 25 in each channel of the image
    private final Vector3 BACKGROUND_COLOUR = new Vector3(0.1);

    // Size of the image to render, in pixels
    private int width, height;

    public Renderer(int width, int height) {
        this.width = width;
        this.height = height;
    }

    /*
     * The colour seen along one ray: the shade of the nearest sphere it meets, or the background.
     */
    protected Vector3 trace(Scene scene, Ray ray) {

        // The nearest hit over all spheres of the scene
        RaycastHit closestHit = scene.findClosestIntersection(ray);

        // A ray that meets nothing sees the background
        Sphere object = closestHit.getObjectHit();
        if (object == null) {
            return BACKGROUND_COLOUR;
        }

        // Otherwise shade the hit: its point P and the surface normal N there
        Vector3 P = closestHit.getLocation();
        Vector3 N = closestHit.getNormal();

        // Phong illumination at P
        return this.illuminate(scene, object, P, N);
    }

    /*
     * Phong's model at the point P with unit normal N on the sphere object:
     * C_diff I_a + C_diff k_d I max(0, N.L) + C_spec k_s I max(0, R.V)^n.
     */
    private Vector3 illuminate(Scene scene, Sphere object, Vector3 P, Vector3 N) {

        PointLight light = scene.getPointLight();
        double distanceToLight = light.getPosition().subtract(P).magnitude();

        Vector3 I_a = scene.getAmbientLighting();
        Vector3 I = light.getIlluminationAt(distanceToLight);

        Vector3 C_diff = object.getColour();           // Diffuse colour
        Vector3 C_spec = new Vector3(1);             // Specular colour

        // Object's Phong coefficients
        double k_d = object.getPhong_kD();
        double k_s = object.getPhong_kS();
        double n = object.getPhong_n();

        // L and V, unit vectors to the light and to the camera at the origin; R, L mirrored in N
        Vector3 L = light.getPosition().subtract(P).normalised();
        Vector3 V = P.scale(-1).normalised();
        Vector3 R = L.reflectIn(N);

        // The cosines of the diffuse and specular terms
        double NdotL = N.dot(L);
        double RdotV = R.dot(V);

        // The three terms, each a colour; * between two colours is per channel
        Vector3 ambient = C_diff.scale(I_a);
        Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, NdotL));
        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, RdotV), n));

        // Their sum
        return ambient.add(diffuse).add(specular);
    }

    /*
     * The image of the scene: one ray through each pixel, row by row from the top.
     */
    public BufferedImage render(Scene scene) {

        // An image with a byte for each of red, green and blue
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);

        // The camera at the origin, looking along z
        Camera camera = new Camera(width, height);

        // Every pixel, row by row
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                Ray ray = camera.castRay(x, y);               // The ray through the pixel
                Vector3 linearRGB = trace(scene, ray);        // The colour it sees
                image.setRGB(x, y, linearRGB.toRGB());        // Clamped and truncated to bytes
            }
            // How much is done
            System.out.println(String.format("%.2f", 100 * y / (float) (height - 1)) + "% completed");
        }
        return image;
    }
}
