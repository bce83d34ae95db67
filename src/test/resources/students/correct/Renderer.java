package gfx.tick1;

import java.awt.image.BufferedImage;

public class Renderer {

    // The colour of a ray that hits nothing
    private final Vector3 BACKGROUND_COLOUR = new Vector3(0.1);

    // The width and height of the image in pixels
    private int width, height;

    public Renderer(int width, int height) {
        this.width = width;
        this.height = height;
    }

    /*
     * Trace the ray through the supplied scene, returning the colour to be rendered.
     */
    protected Vector3 trace(Scene scene, Ray ray) {

        // Find closest intersection of ray in the scene
        RaycastHit closestHit = scene.findClosestIntersection(ray);

        // If no object has been hit, return a background colour
        Sphere object = closestHit.getObjectHit();
        if (object == null) {
            return BACKGROUND_COLOUR;
        }

        // Otherwise calculate colour at intersection and return
        // Get properties of surface at intersection - location, surface normal
        Vector3 P = closestHit.getLocation();
        Vector3 N = closestHit.getNormal();

        // Illuminate the surface
        return this.illuminate(scene, object, P, N);
    }

    /*
     * Illuminate a surface on and object in the scene at a given position P and surface normal N,
     * relative to ray originating at O.
     */
    private Vector3 illuminate(Scene scene, Sphere object, Vector3 P, Vector3 N) {

        PointLight light = scene.getPointLight();
        double distanceToLight = light.getPosition().subtract(P).magnitude();

        Vector3 I_a = scene.getAmbientLighting();
        Vector3 I = light.getIlluminationAt(distanceToLight);

        Vector3 C_diff = object.getColour();  // Diffuse colour
        Vector3 C_spec = new Vector3(1);      // Specular colour

        // Object's Phong coefficients
        double k_d = object.getPhong_kD();
        double k_s = object.getPhong_kS();
        double n = object.getPhong_n();

        // Calculate L, V, and R
        Vector3 L = light.getPosition().subtract(P).normalised();
        Vector3 V = P.scale(-1).normalised();
        Vector3 R = L.reflectIn(N);

        // Calculate NdotL and RdotV
        double NdotL = N.dot(L);
        double RdotV = R.dot(V);

        // Calculate Vector3 ambient, diffuse, and specular terms
        Vector3 ambient = C_diff.scale(I_a);
        Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, NdotL));
        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, RdotV), n));

        return ambient.add(diffuse).add(specular);
    }

    /*
     * Render the scene to an image, one ray per pixel, row by row.
     */
    public BufferedImage render(Scene scene) {

        // Set up image
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);

        // Set up camera
        Camera camera = new Camera(width, height);

        // Loop over all pixels
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                Ray ray = camera.castRay(x, y);               // Cast ray through pixel
                Vector3 linearRGB = trace(scene, ray);        // Trace path of cast ray and determine colour
                image.setRGB(x, y, linearRGB.toRGB());        // Set image colour to traced colour
            }
            // Report progress
            System.out.println(String.format("%.2f", 100 * y / (float) (height - 1)) + "% completed");
        }
        return image;
    }
}
