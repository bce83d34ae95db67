package gfx.tick1.engine.math;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class RayTest {

    @Test
    void evaluateAtWalksAlongTheDirectionFromTheOrigin() {
        Ray ray = new Ray(new Vector3(1, 2, 3), new Vector3(0, 0, 1));
        assertThat(ray.evaluateAt(0)).isEqualTo(new Vector3(1, 2, 3));
        assertThat(ray.evaluateAt(2.5)).isEqualTo(new Vector3(1, 2, 5.5));
    }

    @Test
    void keepsOriginAndDirectionAsGiven() {
        Vector3 origin = new Vector3(0), direction = new Vector3(0, 1, 0);
        Ray ray = new Ray(origin, direction);
        assertThat(ray.getOrigin()).isSameAs(origin);
        assertThat(ray.getDirection()).isSameAs(direction);
    }
}
