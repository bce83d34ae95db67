package gfx.tick1.scene;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.math.Ray;
import gfx.tick1.math.Vector3;
import org.junit.jupiter.api.Test;

class SceneTest {

    private static final Ray FORWARD = new Ray(new Vector3(0), new Vector3(0, 0, 1));

    @Test
    void theNearestOfSeveralSpheresIsReturnedWhateverTheirOrder() {
        Sphere far = new Sphere(new Vector3(0, 0, 10), 1, new Vector3(1));
        Sphere near = new Sphere(new Vector3(0, 0, 5), 1, new Vector3(1));
        Scene scene = new Scene();
        scene.addObject(far);
        scene.addObject(near);
        assertThat(scene.findClosestIntersection(FORWARD).getObjectHit()).isSameAs(near);
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
