package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class SceneTest {

    private static final Ray FORWARD = new Ray(new Vector3(0), new Vector3(0, 0, 1));

    /** Every order of the given items: n! lists. */
    private static <T> List<List<T>> orders(List<T> items) {
        if (items.size() <= 1) {
            return List.of(items);
        }
        List<List<T>> orders = new ArrayList<>();
        for (int i = 0; i < items.size(); i++) {
            List<T> rest = new ArrayList<>(items);
            T first = rest.remove(i);
            for (List<T> order : orders(rest)) {
                List<T> whole = new ArrayList<>(List.of(first));
                whole.addAll(order);
                orders.add(whole);
            }
        }
        return orders;
    }

    @Test
    void theNearestOfSeveralSpheresIsReturnedWhateverTheirOrder() {
        Sphere near = new Sphere(new Vector3(0, 0, 5), 1, new Vector3(1));
        List<Sphere> spheres = List.of(new Sphere(new Vector3(0, 0, 10), 1, new Vector3(1)), near,
                new Sphere(new Vector3(0, 0, 7), 0.5, new Vector3(1)),
                new Sphere(new Vector3(0, 3, 5), 1, new Vector3(1)));
        List<List<Sphere>> orders = orders(spheres);
        assertThat(orders).hasSize(24);
        for (List<Sphere> order : orders) {
            Scene scene = new Scene();
            order.forEach(scene::addObject);
            assertThat(scene.findClosestIntersection(FORWARD).getObjectHit())
                    .as("the sphere hit when they are added in the order of z = %s",
                            order.stream().map(sphere -> SphereGeometry.centre(sphere).z).toList())
                    .isSameAs(near);
        }
    }

    @Test
    void atEqualDistanceTheSphereEarlierInTheFileWins() {
        Sphere first = new Sphere(new Vector3(0, 0, 5), 1, new Vector3(1, 0, 0));
        Sphere second = new Sphere(new Vector3(0, 0, 5), 1, new Vector3(0, 1, 0));
        Scene scene = new Scene();
        scene.addObject(first);
        scene.addObject(second);
        assertThat(scene.findClosestIntersection(FORWARD).getObjectHit()).isSameAs(first);
    }

    @Test
    void anEmptySceneReturnsTheEmptyHit() {
        RaycastHit hit = new Scene().findClosestIntersection(FORWARD);
        assertThat(hit.getObjectHit()).isNull();
        assertThat(hit.getDistance()).isEqualTo(Double.POSITIVE_INFINITY);
    }

    @Test
    void ambientLightDefaultsToWhite() {
        assertThat(new Scene().getAmbientLighting()).isEqualTo(new Vector3(1, 1, 1));
    }
}
