package gfx.tick1.engine.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.parallel.Isolated;

/**
 * Each Phong term on its own. The sphere is pure red and the specular colour white, so the green
 * channel carries only the specular term and red carries diffuse plus specular. The camera ray
 * along +z meets the sphere at P = (0, 0, 4) with N = V = (0, 0, -1).
 */
@Isolated("one test reads what the tick's Renderer prints on System.out, which it swaps for its own")
class RendererTest {

    private static final Ray AXIS = new Ray(new Vector3(0), new Vector3(0, 0, 1));
    private static final Vector3 RED = new Vector3(1, 0, 0);
    private static final Vector3 BLACK = new Vector3(0);
    private static final double TOLERANCE = 1e-15;

    private final Renderer renderer = new ReferenceRenderer(64, 48);

    private static Scene scene(Vector3 ambient, PointLight light) {
        Scene scene = new Scene();
        scene.addObject(new Sphere(new Vector3(0, 0, 5), 1, RED));
        scene.setAmbientLight(ambient);
        scene.setPointLight(light);
        return scene;
    }

    /** I = colour * intensity / (4 pi d^2) for a white light of intensity 100 at distance 4. */
    private static final double I_AT_4 = 100 / (4 * Math.PI * 16);

    @Test
    void aRayThatHitsNothingGetsTheBackgroundColour() {
        Scene scene = scene(new Vector3(1), null);
        assertThat(renderer.trace(scene, new Ray(new Vector3(0), new Vector3(0, 1, 0)))).isEqualTo(new Vector3(0.1));
    }

    @Test
    void ambientTermIsTheDiffuseColourTimesTheAmbientLight() {
        Vector3 colour = renderer.trace(scene(new Vector3(0.5, 0.25, 1), null), AXIS);
        assertThat(colour).isEqualTo(new Vector3(0.5, 0, 0));
    }

    @Test
    void headOnLightGivesFullDiffuseAndFullSpecular() {
        Vector3 colour = renderer.trace(scene(BLACK, new PointLight(new Vector3(0), new Vector3(1), 100)), AXIS);
        assertThat(colour.y).as("specular: k_s I (R.V)^n with R.V = 1").isCloseTo(0.8 * I_AT_4, within(TOLERANCE));
        assertThat(colour.x - colour.y).as("diffuse: k_d I (N.L) with N.L = 1")
                .isCloseTo(0.8 * I_AT_4, within(TOLERANCE));
        assertThat(colour.z).isEqualTo(colour.y);
    }

    @Test
    void diffuseFollowsLambertsCosineAndSpecularTheNthPowerOfRdotV() {
        // The light 4 units from P at 60 degrees from N: N.L = cos 60 and R.V = cos 60.
        double sin60 = Math.sin(Math.toRadians(60)), cos60 = Math.cos(Math.toRadians(60));
        Vector3 lightAt = new Vector3(4 * sin60, 0, 4 - 4 * cos60);
        Vector3 colour = renderer.trace(scene(BLACK, new PointLight(lightAt, new Vector3(1), 100)), AXIS);
        assertThat(colour.y).as("specular").isCloseTo(0.8 * I_AT_4 * Math.pow(0.5, 10), within(1e-12));
        assertThat(colour.x - colour.y).as("diffuse").isCloseTo(0.8 * I_AT_4 * 0.5, within(1e-12));
    }

    @Test
    void lightBehindTheSurfaceAddsNeitherDiffuseNorSpecular() {
        // Light inside the sphere, behind P: N.L = -1 and R.V = -1, both clamped to 0.
        PointLight light = new PointLight(new Vector3(0, 0, 5.5), new Vector3(1), 100);
        Vector3 colour = renderer.trace(scene(new Vector3(0.2), light), AXIS);
        assertThat(colour).isEqualTo(new Vector3(0.2, 0, 0));
    }

    @Test
    void illuminationFallsOffWithTheSquareOfTheDistance() {
        Vector3 near = renderer.trace(scene(BLACK, new PointLight(new Vector3(0, 0, 2), new Vector3(1), 100)), AXIS);
        Vector3 far = renderer.trace(scene(BLACK, new PointLight(new Vector3(0, 0, 0), new Vector3(1), 100)), AXIS);
        assertThat(near.y / far.y).as("light at distance 2 vs 4").isCloseTo(4, within(1e-12));
    }

    @Test
    void lightColourFiltersTheIllumination() {
        Vector3 colour = renderer.trace(scene(BLACK, new PointLight(new Vector3(0), new Vector3(0, 1, 0), 100)), AXIS);
        assertThat(colour.x).as("a green light puts no diffuse light on a red sphere").isZero();
        assertThat(colour.y).as("but its highlight is green").isPositive();
    }

    @Test
    void renderProducesAnRgbImageOfTheRequestedSize() {
        BufferedImage image = renderer.render(scene(new Vector3(1), null));
        assertThat(image.getWidth()).isEqualTo(64);
        assertThat(image.getHeight()).isEqualTo(48);
        assertThat(image.getType()).isEqualTo(BufferedImage.TYPE_INT_RGB);
        assertThat(image.getRGB(0, 0) & 0xFFFFFF).as("corner is background").isEqualTo(0x191919);
        assertThat(image.getRGB(32, 24) & 0xFFFFFF).as("centre is the ambient-lit red sphere").isEqualTo(0xFF0000);
    }

    /**
     * The tick's own Renderer.render, one thread, one castRay per pixel, a line per row on
     * standard output, gives the reference render's image pixel for pixel.
     */
    @Test
    void theTicksRenderGivesTheReferenceImageAndPrintsARowAtATime() {
        Scene scene = BundledScenes.load(BundledScenes.TICK1);
        PrintStream standardOut = System.out;
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        BufferedImage ticks;
        try {
            System.setOut(new PrintStream(printed, true));
            ticks = new Renderer(64, 48).render(scene);
        } finally {
            System.setOut(standardOut);
        }
        BufferedImage reference = new ReferenceRenderer(64, 48).render(scene);
        assertThat(ticks.getRGB(0, 0, 64, 48, null, 0, 64)).isEqualTo(reference.getRGB(0, 0, 64, 48, null, 0, 64));
        assertThat(printed.toString().lines()).hasSize(48).endsWith("100.00% completed");
    }
}
