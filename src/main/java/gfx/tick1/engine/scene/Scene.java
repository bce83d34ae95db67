package gfx.tick1.engine.scene;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * The spheres, the ambient light and the one point light of a Tick 1 scene.
 *
 * <p>It keeps the starter code's mutable shape ({@code addObject}, {@code setPointLight}) because
 * students' code calls it that way; the loader builds one and nothing changes it afterwards.
 */
public final class Scene {

    /** The starter code's ambient light when a scene has no ambient-light element: white. */
    public static final Vector3 DEFAULT_AMBIENT = new Vector3(1);

    private final List<Sphere> objects = new ArrayList<>();
    private Vector3 ambientLight = DEFAULT_AMBIENT;
    private PointLight pointLight;
    private Intersection intersection = Intersection.DEFAULT;

    /**
     * The same spheres and lights, intersected by {@code method} in {@link #findClosestIntersection(Ray)}:
     * how the reference renderer gives the tick's Renderer.trace, which calls that method, another
     * intersection method.
     */
    public Scene using(Intersection method) {
        Scene scene = new Scene();
        scene.objects.addAll(objects);
        scene.ambientLight = ambientLight;
        scene.pointLight = pointLight;
        scene.intersection = method;
        return scene;
    }

    public void addObject(Sphere object) {
        objects.add(object);
    }

    public List<Sphere> getObjects() {
        return Collections.unmodifiableList(objects);
    }

    /** The nearest hit over all spheres, found with this scene's {@link Intersection} (by default the robust one). */
    public RaycastHit findClosestIntersection(Ray ray) {
        return findClosestIntersection(ray, intersection);
    }

    /**
     * The nearest hit over all spheres. A later sphere replaces the current hit only when
     * strictly closer, so at equal distances the sphere earlier in the file wins.
     */
    public RaycastHit findClosestIntersection(Ray ray, Intersection intersection) {
        RaycastHit closest = new RaycastHit();
        for (Sphere object : objects) {
            RaycastHit hit = intersection.find(object, ray);
            if (hit.getDistance() < closest.getDistance()) {
                closest = hit;
            }
        }
        return closest;
    }

    public Vector3 getAmbientLighting() {
        return ambientLight;
    }

    public void setAmbientLight(Vector3 ambientLight) {
        this.ambientLight = ambientLight;
    }

    /** The scene's point light, or null when the file has none (then only ambient light shades). */
    public PointLight getPointLight() {
        return pointLight;
    }

    public void setPointLight(PointLight pointLight) {
        this.pointLight = pointLight;
    }
}
