package gfx.tick1.grade.grading;

import gfx.tick1.grade.grading.ProbeAnswers.Answer;
import gfx.tick1.grade.grading.ProbeAnswers.Colour;
import gfx.tick1.grade.grading.ProbeAnswers.Failed;
import gfx.tick1.grade.grading.ProbeAnswers.Hit;
import gfx.tick1.grade.grading.ProbeAnswers.None;
import gfx.tick1.grade.harness.ProbeCalls;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * Judges each {@link Probe} on the student's answers. A failed probe's fact says only what the
 * call returned, measured against the reference: "your illuminate gives negative diffuse light
 * when N.L &lt; 0". Where the numbers show a known shape (the farther root, 4 pi too strong), the
 * fact names it; otherwise it says what differs and no more.
 */
final class ProbeJudge {

    /** How a probe came out. */
    enum State { HOLDS, FAILS, NOT_JUDGED }

    /** A probe's outcome; for a failure, the fact and the section to reread. */
    record Judgement(Probe probe, State state, String fact, String section) {
    }

    /** Relative (and, near 0, absolute) tolerance: correct code written another way differs in the last bits. */
    private static final double TOLERANCE = 1e-9;

    private final ProbeAnswers answers;
    private final Map<Probe, Judgement> judged = new EnumMap<>(Probe.class);

    private ProbeJudge(ProbeAnswers answers) {
        this.answers = answers;
    }

    /** Every probe's outcome, in the catalogue's order. */
    static List<Judgement> judge(ProbeAnswers answers) {
        ProbeJudge judge = new ProbeJudge(answers);
        for (Probe probe : Probe.values()) {
            boolean ready = probe.requires().stream().allMatch(p -> judge.judged.get(p).state() == State.HOLDS);
            judge.judged.put(probe, ready ? judge.judgeOne(probe) : new Judgement(probe, State.NOT_JUDGED, null, null));
        }
        return new ArrayList<>(judge.judged.values());
    }

    private Judgement judgeOne(Probe probe) {
        try {
            String fact = switch (probe.method()) {
                case "intersectionWith" -> intersection(probe);
                default -> illumination(probe);
            };
            return fact == null ? new Judgement(probe, State.HOLDS, null, null)
                    : new Judgement(probe, State.FAILS, fact, section(probe, fact));
        } catch (NoAnswer e) {
            return new Judgement(probe, State.FAILS, "your " + probe.method() + " " + e.getMessage() + " for "
                    + probe.situation(), probe.section());
        }
    }

    /** Facts that name a mistake of another section than the probe's own. */
    private static String section(Probe probe, String fact) {
        if (fact.contains("4 pi")) {
            return "section 5, \"Phong illumination code\" (Vector3 I = light.getIlluminationAt(distanceToLight))";
        }
        if (fact.contains("not normalised")) {
            return "section 5, Figure 6(a): N, L, R and V should all be unit vectors";
        }
        if (fact.contains("I_a, not C_diff I_a")) {
            return Probe.AMBIENT.section();
        }
        return probe.section();
    }

    private String intersection(Probe probe) {
        return switch (probe) {
            case HIT -> {
                Answer a = answer("outside");
                yield a instanceof None ? "your intersectionWith finds no hit for " + probe.situation()
                        : ((Hit) hit(a)).sameSphere() ? null
                        : "your intersectionWith returns a hit that does not name the sphere "
                        + "(new RaycastHit(this, ...))";
            }
            case MISS, POINTS_AWAY, BEHIND -> {
                Answer a = answer(probe == Probe.MISS ? "miss" : probe == Probe.POINTS_AWAY ? "away" : "behind");
                yield a instanceof None ? null : hit(a) == null ? null
                        : "your intersectionWith returns a hit for " + probe.situation();
            }
            case NEAREST_ROOT -> {
                double s = ((Hit) hit(answer("outside"))).distance(), expected = reference("outside");
                yield close(s, expected) ? null : close(s, 6) ? "your intersectionWith takes the farther root: "
                        + "for a ray from outside it returns s = 6, where the nearer hit is at s = 4"
                        : "your intersectionWith returns a distance other than the nearest root for "
                        + probe.situation();
            }
            case POINT -> {
                Hit hit = (Hit) hit(answer("outside"));
                ProbeCalls.Intersection call = intersectionCall("outside");
                double[] expected = ProbeReference.add(call.origin(), ProbeReference.scale(call.direction(),
                        hit.distance()));
                yield close(hit.point(), expected) ? null
                        : "your intersectionWith's hit point is not O + s D for the distance s it returns";
            }
            case NORMAL -> {
                Hit hit = (Hit) hit(answer("outside"));
                double[] outward = ProbeReference.subtract(hit.point(), intersectionCall("outside").centre());
                double length = Math.sqrt(ProbeReference.dot(outward, outward));
                yield close(hit.normal(), ProbeReference.scale(outward, 1 / length)) ? null
                        : "your intersectionWith's normal is not the outward unit normal at the hit point";
            }
            case GRAZE, INSIDE, ON_SURFACE -> edgeCase(probe);
            default -> throw new IllegalArgumentException(probe.name());
        };
    }

    private String edgeCase(Probe probe) {
        String name = probe == Probe.GRAZE ? "graze" : probe == Probe.INSIDE ? "inside" : "surface";
        Answer a = answer(name);
        if (a instanceof None) {
            return "your intersectionWith finds no hit for " + probe.situation()
                    + (probe == Probe.GRAZE ? " (a zero discriminant)" : "");
        }
        Hit hit = (Hit) hit(a);
        if (hit.sameSphere() && close(hit.distance(), reference(name))) {
            return null;
        }
        if (probe == Probe.ON_SURFACE && hit.distance() == 0) {
            return "your intersectionWith accepts a root s = 0: a ray that starts on a sphere's surface hits it "
                    + "where it starts";
        }
        return "your intersectionWith returns a distance other than the nearest positive root for "
                + probe.situation();
    }

    private String illumination(Probe probe) {
        return switch (probe) {
            case PLACEHOLDER -> placeholder();
            case SCALE -> scale();
            case CHANNELS -> channels();
            case AMBIENT -> {
                double[] c = colour("ambient");
                yield close(c, expected("ambient")) ? null : close(c, new double[3])
                        ? "your illuminate has no ambient term: with the point light off the colour is black, not "
                        + "C_diff I_a"
                        : "with the point light off, your illuminate's colour is not the ambient term C_diff I_a";
            }
            case DIFFUSE -> {
                double d = diffuse("near"), expected = diffuseExpected("near");
                yield close(d, expected) ? null : close(d, 0) ? "your illuminate has no diffuse term C_diff k_d I "
                        + "max(0, N.L): with the light along the normal, only the specular light is there"
                        : close(d, 4 * Math.PI * expected) ? "your illuminate's light is 4 pi (about 12.6) times too "
                        + "strong: I is intensity / (4 pi d^2)"
                        : "with the light along the normal at distance 1, your illuminate's diffuse term is not "
                        + "C_diff k_d I";
            }
            case FALL_OFF -> fallOff();
            case SPECULAR -> close(colour("near")[1], 0) && close(colour("side")[1], 0)
                    ? "your illuminate has no specular term: no highlight, even where R points at the camera" : null;
            case CAMERA_DIRECTION -> cameraDirection();
            case SPECULAR_WITH_I -> close(colour("far")[1], expected("far")[1]) ? null
                    : close(colour("far")[1], colour("near")[1]) ? "your illuminate's specular term leaves out I: "
                    + "the highlight does not weaken with the light's distance"
                    : "with the light at distance 2, your illuminate's specular term is not C_spec k_s I";
            case V_UNIT -> close(colour("camera-far")[1], expected("camera-far")[1]) ? null
                    : colour("camera-far")[1] > expected("camera-far")[1] ? "your illuminate's highlight grows "
                    + "with the distance to the camera: V is not normalised"
                    : "with the camera at distance 2, your illuminate's specular term is not C_spec k_s I where R "
                    + "points at the camera";
            case REFLECTION -> close(colour("oblique")[1], expected("oblique")[1]) ? null
                    : "with the light at an angle, your illuminate's highlight is not where L mirrored in N points";
            case N_DOT_L_CLAMPED -> close(diffuse("light-behind"), 0) ? null : diffuse("light-behind") < 0
                    ? "your illuminate gives negative diffuse light when N.L < 0 (the light behind the surface)"
                    : "your illuminate gives diffuse light when N.L < 0 (the light behind the surface)";
            case R_DOT_V_CLAMPED -> close(colour("side")[1], 0) ? null
                    : "your illuminate gives a specular highlight where R points away from the camera (R.V < 0)";
            default -> throw new IllegalArgumentException(probe.name());
        };
    }

    private String placeholder() {
        for (String name : List.of("ambient", "near", "side", "oblique")) {
            if (!close(colour(name), illuminationCall(name).colour())) {
                return null;
            }
        }
        return "your illuminate returns the sphere's colour C_diff whatever the light (the starter code's "
                + "placeholder)";
    }

    private String scale() {
        for (double factor : new double[] {255, 1 / 255.0}) {
            if (close(colour("ambient"), ProbeReference.scale(expected("ambient"), factor))
                    && close(colour("near"), ProbeReference.scale(expected("near"), factor))) {
                return factor > 1 ? "your illuminate's colours are 255 times too large: r, g, b run from 0 to 1, "
                        + "and toRGB() makes bytes of them"
                        : "your illuminate's colours are 255 times too small: r, g, b already run from 0 to 1";
            }
        }
        return null;
    }

    private String channels() {
        boolean white = true, crossed = false;
        for (String name : List.of("red", "green", "blue")) {
            double[] c = colour(name), surface = illuminationCall(name).colour();
            white &= close(c, new double[] {1, 1, 1});
            for (int i = 0; i < 3; i++) {
                crossed |= surface[i] == 0 && !close(c[i], 0);
            }
        }
        return !crossed ? null : white ? "your illuminate's ambient term is I_a, not C_diff I_a: a red surface "
                + "in white ambient light comes out white"
                : "your illuminate moves light between colour channels: a pure red, green or blue surface in white "
                + "ambient light comes out in another channel";
    }

    private String fallOff() {
        double ratio = diffuse("far") / diffuse("near");
        return close(ratio, 0.25) ? null : close(ratio, 1)
                ? "your illuminate's light does not weaken with distance: it should fall off as 1 / d^2"
                : close(ratio, 0.5) ? "your illuminate's diffuse term falls off as 1 / d, not 1 / d^2: N.L grows "
                + "with the distance to the light, so L is not normalised"
                : "your illuminate's diffuse term at distance 2 is not a quarter of that at distance 1 (1 / d^2)";
    }

    private String cameraDirection() {
        double atCamera = colour("near")[1];
        if (close(atCamera, 0) && !close(colour("side")[1], 0)) {
            return "your illuminate's V points away from the camera: the highlight is where R points away from "
                    + "it, and none where R points at it";
        }
        return close(atCamera, expected("near")[1]) ? null
                : "where R points at the camera, your illuminate's specular term is not C_spec k_s I";
    }

    /** Red minus green at a call whose surface has no green: the diffuse term's red. */
    private double diffuse(String name) {
        double[] c = colour(name);
        return c[0] - c[1];
    }

    private double diffuseExpected(String name) {
        double[] c = expected(name);
        return c[0] - c[1];
    }

    private Answer answer(String name) {
        return answers.get(name);
    }

    /** The answer as a hit or none; a call that gave neither has no answer to judge. */
    private static Answer hit(Answer a) {
        if (a instanceof Hit || a instanceof None) {
            return a;
        }
        throw new NoAnswer(how(a));
    }

    private double[] colour(String name) {
        Answer a = answers.get(name);
        if (a instanceof Colour colour) {
            return colour.rgb();
        }
        throw new NoAnswer(a instanceof Failed failed && failed.how().equals("absent")
                ? "is missing (no illuminate(Scene, Sphere, Vector3, Vector3) returning a Vector3)" : how(a));
    }

    private static String how(Answer a) {
        String how = a instanceof Failed failed ? failed.how() : "";
        return switch (how) {
            case "null" -> "returns null";
            case "threw" -> "throws an exception";
            case "timeout" -> "does not return within half a second";
            default -> "gives no answer";
        };
    }

    private static double reference(String name) {
        return ProbeReference.distance(intersectionCall(name));
    }

    private static double[] expected(String name) {
        return ProbeReference.terms(illuminationCall(name)).sum();
    }

    private static ProbeCalls.Intersection intersectionCall(String name) {
        return ProbeCalls.INTERSECTIONS.stream().filter(c -> c.name().equals(name)).findFirst().orElseThrow();
    }

    private static ProbeCalls.Illumination illuminationCall(String name) {
        return ProbeCalls.ILLUMINATIONS.stream().filter(c -> c.name().equals(name)).findFirst().orElseThrow();
    }

    static boolean close(double a, double b) {
        return Math.abs(a - b) <= TOLERANCE * Math.max(1, Math.max(Math.abs(a), Math.abs(b)));
    }

    private static boolean close(double[] a, double[] b) {
        return close(a[0], b[0]) && close(a[1], b[1]) && close(a[2], b[2]);
    }

    /** A call the probe needs gave no answer: the probe fails with how. */
    private static final class NoAnswer extends RuntimeException {
        private static final long serialVersionUID = 1L;

        NoAnswer(String how) {
            super(how, null, false, false);
        }
    }
}
