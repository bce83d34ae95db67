package gfx.tick1.command.shared.diagnosis;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.Camera;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import java.awt.image.BufferedImage;
import java.util.function.Function;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Mistakes the catalogue does not know, each rendered on both scenes a student renders: none may
 * ever be called correct, however close it comes, and none may be named as a catalogued mistake.
 */
class UncataloguedMistakesTest {

    /** What the slip changes: the Phong terms, given the quantities of illuminate. */
    private record Shading(Vector3 C_diff, Vector3 I_a, Vector3 I, Vector3 N, Vector3 L, Vector3 V, Vector3 R) {

        Vector3 ambient() {
            return C_diff.scale(I_a);
        }

        Vector3 diffuse(double k_d) {
            return C_diff.scale(I).scale(k_d * Math.max(0, N.dot(L)));
        }

        Vector3 specular(double k_s, double n) {
            return new Vector3(1).scale(I).scale(k_s * Math.pow(Math.max(0, R.dot(V)), n));
        }
    }

    static Stream<Arguments> mistakes() {
        return Stream.of(
                Arguments.of("k_s of 0.5", (Function<Shading, Vector3>) s ->
                        s.ambient().add(s.diffuse(0.8)).add(s.specular(0.5, 10))),
                Arguments.of("exponent n of 20", (Function<Shading, Vector3>) s ->
                        s.ambient().add(s.diffuse(0.8)).add(s.specular(0.8, 20))),
                // (A diffuse term without C_diff and a highlight in the sphere's colour are catalogued now.)
                Arguments.of("ambient term twice", (Function<Shading, Vector3>) s ->
                        s.ambient().scale(2).add(s.diffuse(0.8)).add(s.specular(0.8, 10))),
                Arguments.of("specular term without I, at half strength", (Function<Shading, Vector3>) s ->
                        s.ambient().add(s.diffuse(0.8)).add(new Vector3(1).scale(0.8
                                * Math.pow(Math.max(0, s.R().dot(s.V())), 10)).scale(0.5))),
                Arguments.of("exponent n of 5", (Function<Shading, Vector3>) s ->
                        s.ambient().add(s.diffuse(0.8)).add(s.specular(0.8, 5))),
                Arguments.of("diffuse term twice", (Function<Shading, Vector3>) s ->
                        s.ambient().add(s.diffuse(0.8)).add(s.diffuse(0.8)).add(s.specular(0.8, 10))),
                Arguments.of("a light 1% too weak", (Function<Shading, Vector3>) s -> {
                    Shading weaker = new Shading(s.C_diff(), s.I_a(), s.I().scale(0.99), s.N(), s.L(), s.V(), s.R());
                    return weaker.ambient().add(weaker.diffuse(0.8)).add(weaker.specular(0.8, 10));
                }));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("mistakes")
    void isNeverCalledCorrect(String name, Function<Shading, Vector3> shading) {
        for (String sceneName : BundledScenes.STUDENT_SCENES) {
            Scene scene = BundledScenes.load(sceneName);
            Diagnosis diagnosis = new Diagnoser(0, 1).diagnose(render(scene, shading, 160, 120), scene);
            String report = sceneName + ":\n" + String.join("\n", diagnosis.report());
            assertThat(diagnosis.verdict()).as(report).isEqualTo(Diagnosis.Verdict.UNSURE);
            assertThat(report).doesNotContain("full Phong model", "likely cause", "closest: ")
                    .contains("verdict: unsure: ");
            assertThat(report.lines().filter(line -> line.matches("  \\d+[.=] .*"))).as(report).hasSizeBetween(1, 3);
            assertThat(report.lines().filter(line -> line.startsWith("if it is "))).as(report)
                    .hasSizeLessThanOrEqualTo(3);
        }
    }

    /** Renderer's trace and illuminate, with the terms summed as {@code shading} says. */
    private static BufferedImage render(Scene scene, Function<Shading, Vector3> shading, int width, int height) {
        Camera camera = new Camera(width, height);
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                RaycastHit hit = scene.findClosestIntersection(camera.castRay(x, y));
                Vector3 colour = new Vector3(0.1);
                Sphere object = hit.getObjectHit();
                if (object != null) {
                    Vector3 P = hit.getLocation();
                    PointLight light = scene.getPointLight();
                    double distanceToLight = light.getPosition().subtract(P).magnitude();
                    Vector3 L = light.getPosition().subtract(P).normalised();
                    Vector3 V = P.scale(-1).normalised();
                    colour = shading.apply(new Shading(object.getColour(), scene.getAmbientLighting(),
                            light.getIlluminationAt(distanceToLight), hit.getNormal(), L, V,
                            L.reflectIn(hit.getNormal())));
                }
                image.setRGB(x, y, colour.toRGB());
            }
        }
        return image;
    }
}
