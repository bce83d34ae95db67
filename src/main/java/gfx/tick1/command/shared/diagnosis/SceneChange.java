package gfx.tick1.command.shared.diagnosis;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * A scene file that differs from the one asked for in one value: a light's or a sphere's
 * colour, the light's intensity or position, or a sphere's centre or radius. These are the slips
 * of writing a scene file by hand: a value kept from the handout's example scene, a sign lost, an
 * attribute left out (its default, 0 for a coordinate, 100 for an intensity, white for the
 * ambient light).
 *
 * @param what    the value, as a person names it: "ambient", "sphere 2's colour"
 * @param theirs  the value in the changed scene, as a scene file writes it ("#333333", "(0.55, 0.16, 3.5)")
 * @param asked   the value in the scene asked for, written the same way
 * @param scene   the scene with the one change
 */
public record SceneChange(String what, String theirs, String asked, Scene scene) {

    /** "ambient #333333 where section 3 asks for #555555", or "... where tick1.xml has ..." for another scene. */
    public String describe(String askedBy) {
        return what + " " + theirs + " where " + askedBy + " " + asked;
    }

    /**
     * Every scene one slip away from {@code scene}, the values kept from {@code example} (another
     * scene a student has seen; null for none) among the slips.
     */
    public static List<SceneChange> around(Scene scene, Scene example) {
        List<SceneChange> changes = new ArrayList<>();
        Set<Vector3> colours = new LinkedHashSet<>();
        if (example != null) {
            colours.add(example.getAmbientLighting());
            if (example.getPointLight() != null) {
                colours.add(example.getPointLight().getColour());
            }
            example.getObjects().forEach(sphere -> colours.add(sphere.getColour()));
        }
        scene.getObjects().forEach(sphere -> colours.add(sphere.getColour()));
        colours.add(Scene.DEFAULT_AMBIENT);
        Vector3 ambient = scene.getAmbientLighting();
        for (Vector3 colour : colours) {
            if (!colour.equals(ambient)) {
                Scene changed = copy(scene, scene.getPointLight());
                changed.setAmbientLight(colour);
                changes.add(new SceneChange("ambient", hex(colour), hex(ambient), changed));
            }
        }
        PointLight light = scene.getPointLight();
        if (light != null) {
            lightChanges(scene, light, example == null ? null : example.getPointLight(), colours, changes);
        }
        List<Sphere> spheres = scene.getObjects();
        Sphere exampleSphere = example == null || example.getObjects().isEmpty() ? null : example.getObjects().get(0);
        for (int i = 0; i < spheres.size(); i++) {
            sphereChanges(scene, i, exampleSphere, colours, changes);
        }
        return changes;
    }

    private static void lightChanges(Scene scene, PointLight light, PointLight example, Set<Vector3> colours,
            List<SceneChange> changes) {
        for (Vector3 colour : colours) {
            if (!colour.equals(light.getColour())) {
                changes.add(new SceneChange("the point light's colour", hex(colour), hex(light.getColour()),
                        copy(scene,
                                new PointLight(light.getPosition(), colour, light.getIntensity()))));
            }
        }
        Set<Double> intensities = new LinkedHashSet<>(List.of(100.0));
        if (example != null) {
            intensities.add(example.getIntensity());
        }
        for (double intensity : intensities) {
            if (intensity != light.getIntensity()) {
                changes.add(new SceneChange("the point light's intensity", number(intensity),
                        number(light.getIntensity()), copy(scene,
                                new PointLight(light.getPosition(), light.getColour(), intensity))));
            }
        }
        for (Vector3 position : slips(light.getPosition(), example == null ? null : example.getPosition())) {
            changes.add(new SceneChange("the point light at", point(position), point(light.getPosition()),
                    copy(scene, new PointLight(position, light.getColour(),
                            light.getIntensity()))));
        }
    }

    private static void sphereChanges(Scene scene, int index, Sphere example, Set<Vector3> colours,
            List<SceneChange> changes) {
        Sphere sphere = scene.getObjects().get(index);
        Vector3 centre = SphereGeometry.centre(sphere);
        double radius = SphereGeometry.radius(sphere);
        String name = "sphere " + (index + 1) + "'s ";
        for (Vector3 colour : colours) {
            if (!colour.equals(sphere.getColour())) {
                changes.add(new SceneChange(name + "colour", hex(colour), hex(sphere.getColour()),
                        replace(scene, index, new Sphere(centre, radius, colour))));
            }
        }
        for (Vector3 position : slips(centre, example == null ? null : SphereGeometry.centre(example))) {
            changes.add(new SceneChange(name + "centre", point(position), point(centre),
                    replace(scene, index, new Sphere(position, radius, sphere.getColour()))));
        }
        Set<Double> radii = new LinkedHashSet<>(List.of(1.0));
        if (example != null) {
            radii.add(SphereGeometry.radius(example));
        }
        for (double r : radii) {
            if (r != radius) {
                changes.add(new SceneChange(name + "radius", number(r), number(radius),
                        replace(scene, index, new Sphere(centre, r, sphere.getColour()))));
            }
        }
    }

    /** A position with one coordinate's sign lost or the coordinate left out (0), or the example's. */
    private static Set<Vector3> slips(Vector3 position, Vector3 example) {
        Set<Vector3> slips = new LinkedHashSet<>();
        double[] xyz = {position.x, position.y, position.z};
        for (int axis = 0; axis < 3; axis++) {
            for (double value : xyz[axis] == 0 ? new double[0] : new double[] {-xyz[axis], 0}) {
                double[] changed = xyz.clone();
                changed[axis] = value;
                slips.add(new Vector3(changed[0], changed[1], changed[2]));
            }
        }
        if (example != null) {
            slips.add(example);
        }
        slips.removeIf(position::equals);
        return slips;
    }

    private static Scene replace(Scene scene, int index, Sphere sphere) {
        List<Sphere> spheres = new ArrayList<>(scene.getObjects());
        spheres.set(index, sphere);
        Scene changed = new Scene();
        changed.setAmbientLight(scene.getAmbientLighting());
        changed.setPointLight(scene.getPointLight());
        spheres.forEach(changed::addObject);
        return changed;
    }

    private static Scene copy(Scene scene, PointLight light) {
        Scene changed = new Scene();
        changed.setAmbientLight(scene.getAmbientLighting());
        changed.setPointLight(light);
        scene.getObjects().forEach(changed::addObject);
        return changed;
    }

    /** Whether two scenes have the same lights and the same spheres in the same order. */
    public static boolean same(Scene a, Scene b) {
        if (!a.getAmbientLighting().equals(b.getAmbientLighting()) || a.getObjects().size() != b.getObjects().size()
                || (a.getPointLight() == null) != (b.getPointLight() == null)) {
            return false;
        }
        PointLight p = a.getPointLight(), q = b.getPointLight();
        if (p != null && !(p.getPosition().equals(q.getPosition()) && p.getColour().equals(q.getColour())
                && p.getIntensity() == q.getIntensity())) {
            return false;
        }
        for (int i = 0; i < a.getObjects().size(); i++) {
            Sphere s = a.getObjects().get(i), t = b.getObjects().get(i);
            if (!(SphereGeometry.centre(s).equals(SphereGeometry.centre(t))
                    && SphereGeometry.radius(s) == SphereGeometry.radius(t) && s.getColour().equals(t.getColour()))) {
                return false;
            }
        }
        return true;
    }

    /** A colour as a scene file writes it: each channel of 0 to 1 as two hex digits. */
    static String hex(Vector3 colour) {
        return String.format(Locale.ROOT, "#%02X%02X%02X", level(colour.x), level(colour.y), level(colour.z));
    }

    private static long level(double channel) {
        return Math.max(0, Math.min(255, Math.round(channel * 255)));
    }

    private static String point(Vector3 p) {
        return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
    }

    private static String number(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? String.valueOf((long) value)
                : String.valueOf(value);
    }
}
