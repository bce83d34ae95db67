package gfx.tick1.engine.render;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import java.util.Random;

/**
 * Random scenes of the kind in {@code scenes/} outside {@code hard/}: one to twelve spheres of
 * radius 0.05 to 3 around the view, some behind the camera, none containing it or within 0.1 of
 * it; coordinates with three decimals, as people write them; one white light of intensity 20 to
 * 1000 anywhere in a 20-unit box; random colours and ambient light.
 */
final class OrdinaryScenes {

    private OrdinaryScenes() {
    }

    static Scene generate(Random random) {
        Scene scene = new Scene();
        int spheres = 1 + random.nextInt(12);
        for (int i = 0; i < spheres; i++) {
            double radius = decimal(0.05 + 2.95 * random.nextDouble());
            Vector3 centre;
            do {
                centre = new Vector3(decimal(10 * random.nextDouble() - 5), decimal(8 * random.nextDouble() - 4),
                        decimal(30 * random.nextDouble() - 5));
            } while (centre.magnitude() < radius + 0.1);
            scene.addObject(new Sphere(centre, radius, colour(random)));
        }
        scene.setAmbientLight(new Vector3(random.nextInt(128) / 255.0));
        Vector3 light = new Vector3(decimal(20 * random.nextDouble() - 10), decimal(20 * random.nextDouble() - 10),
                decimal(20 * random.nextDouble() - 5));
        scene.setPointLight(new PointLight(light, colour(random), decimal(20 + 980 * random.nextDouble())));
        return scene;
    }

    private static Vector3 colour(Random random) {
        return new Vector3(random.nextInt(256) / 255.0, random.nextInt(256) / 255.0, random.nextInt(256) / 255.0);
    }

    /** The double a scene file with three decimals would give. */
    private static double decimal(double value) {
        return Double.parseDouble(String.format(java.util.Locale.ROOT, "%.3f", value));
    }
}
