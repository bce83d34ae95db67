package gfx.tick1.command.shared.behaviour;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.Isolated;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Correct solutions written in other styles than ours behave as ours on every input, tested or
 * not: the comparison may speak only of what the code does, never of how it is written.
 */
@Isolated("its probes run in this JVM, each call of the student's methods within a time limit "
        + "(AnswerLog.CALL_MILLIS) that a class running beside it could use up")
class BehaviourStylesTest {

    static Stream<Arguments> styles() {
        CalledSolution correct = CalledSolution.correct();
        return Stream.of(
                Arguments.of("renamed locals", correct.intersection("""
                        double disc = b * b - 4 * a * c;
                        if (disc < 0) {
                            return new RaycastHit();
                        }
                        double near = (-b - Math.sqrt(disc)) / (2 * a);
                        double far = (-b + Math.sqrt(disc)) / (2 * a);
                        double t = near > 0 ? near : far;
                        if (t > 0) {
                            Vector3 hitPoint = ray.evaluateAt(t);
                            return new RaycastHit(this, t, hitPoint, getNormalAt(hitPoint));
                        }
                        return new RaycastHit();
                """)),
                Arguments.of("if/else for the ternary", correct.intersection("""
                        double discriminant = Math.pow(b, 2) - 4 * a * c;
                        if (discriminant < 0)
                            return new RaycastHit();
                        double s1 = (-b - Math.sqrt(discriminant)) / (2 * a),
                                s2 = (-b + Math.sqrt(discriminant)) / (2 * a);
                        double s;
                        if (s1 > 0) {
                            s = s1;
                        } else {
                            s = s2;
                        }
                        if (s <= 0) {
                            return new RaycastHit();
                        }
                        Vector3 point = ray.evaluateAt(s);
                        return new RaycastHit(this, s, point, this.getNormalAt(point));
                """)),
                Arguments.of("split roots, the square root once", correct.intersection("""
                        double disc = b * b - 4 * a * c;
                        if (disc < 0) {
                            return new RaycastHit();
                        }
                        double root = Math.sqrt(disc);
                        double first = (-b - root) / (2 * a);
                        if (first > 0) {
                            Vector3 p = ray.evaluateAt(first);
                            return new RaycastHit(this, first, p, getNormalAt(p));
                        }
                        double second = (-b + root) / (2 * a);
                        if (second > 0) {
                            Vector3 p = ray.evaluateAt(second);
                            return new RaycastHit(this, second, p, getNormalAt(p));
                        }
                        return new RaycastHit();
                """)),
                Arguments.of("half b", correct.intersection("""
                        double halfB = D.dot(O.subtract(C));
                        double quarter = halfB * halfB - a * c;
                        if (quarter < 0) {
                            return new RaycastHit();
                        }
                        double s = (-halfB - Math.sqrt(quarter)) / a;
                        if (!(s > 0)) {
                            s = (-halfB + Math.sqrt(quarter)) / a;
                        }
                        if (!(s > 0)) {
                            return new RaycastHit();
                        }
                        Vector3 point = O.add(D.scale(s));
                        return new RaycastHit(this, s, point, point.subtract(C).normalised());
                """)),
                Arguments.of("the clamp moved into NdotL", correct.shading("""
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        double NdotL = Math.max(0, N.dot(L));
                        double RdotV = Math.max(0.0, R.dot(V));
                        Vector3 ambient = C_diff.scale(I_a);
                        Vector3 diffuse = C_diff.scale(I).scale(k_d * NdotL);
                        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(RdotV, n));
                        return ambient.add(diffuse).add(specular);
                """)),
                Arguments.of("extra normalisations", correct.shading("""
                        Vector3 unitN = N.normalised();
                        Vector3 L = light.getPosition().subtract(P).normalised().normalised();
                        Vector3 V = new Vector3(0).subtract(P).normalised();
                        Vector3 R = L.reflectIn(unitN).normalised();
                        double NdotL = unitN.dot(L);
                        double RdotV = R.normalised().dot(V.normalised());
                        Vector3 ambient = C_diff.scale(I_a);
                        Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, NdotL));
                        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, RdotV), n));
                        return ambient.add(diffuse).add(specular);
                """)),
                Arguments.of("if for the clamps, terms in another order, R by hand", correct.shading("""
                        Vector3 toLight = light.getPosition().subtract(P);
                        Vector3 L = toLight.scale(1 / toLight.magnitude());
                        Vector3 V = P.scale(-1 / P.magnitude());
                        Vector3 R = N.scale(2 * L.dot(N)).subtract(L);
                        double NdotL = N.dot(L);
                        if (NdotL < 0) {
                            NdotL = 0;
                        }
                        double RdotV = R.dot(V);
                        if (RdotV < 0) RdotV = 0;
                        Vector3 specular = I.scale(k_s * Math.pow(RdotV, n)).scale(C_spec);
                        Vector3 diffuse = I.scale(C_diff).scale(k_d).scale(NdotL);
                        return specular.add(diffuse).add(I_a.scale(C_diff));
                """)));
    }

    /** Styles of this project's own writing, each as its two files. */
    static Stream<Arguments> writtenStyles() {
        return WrittenStyles.all().values().stream().map(style -> Arguments.of(style.name(),
                new CalledSolution(style.sphere(), style.renderer())));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("writtenStyles")
    void aCorrectSolutionOfOurOwnStyleBehavesAsOurs(String style, CalledSolution solution, @TempDir Path folder)
            throws Exception {
        aCorrectSolutionInAnotherStyleBehavesAsOurs(style, solution, folder);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("styles")
    void aCorrectSolutionInAnotherStyleBehavesAsOurs(String style, CalledSolution solution, @TempDir Path folder)
            throws Exception {
        BehaviourFindings findings = solution.findings(folder);
        assertThat(findings.ran()).as("the style \"%s\" was run", style).isTrue();
        assertThat(findings.facts()).as("the tested findings of the style \"%s\"", style).isEmpty();
        assertThat(findings.untested()).as("the untested notes of the style \"%s\"", style).isEmpty();
    }
}
