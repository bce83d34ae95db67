package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.behaviour.Answers.Answer;
import gfx.tick1.command.shared.behaviour.Answers.Colour;
import gfx.tick1.command.shared.behaviour.Answers.Failed;
import gfx.tick1.command.shared.behaviour.Answers.Hit;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs;
import gfx.tick1.engine.math.Vector3;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.function.Function;

/**
 * The inputs and answers of the behaviour comparison in words, with numbers as short as they
 * can be written exactly (0.6, not 0.6000000000000001, is kept only when it is the double given),
 * and how round an input is, to choose the simplest counterexample.
 */
final class Words {

    /** How a long number is written: in seven significant digits, or in every digit that reads back as it. */
    enum Digits { SEVEN, EVERY }

    private Words() {
    }

    /**
     * "yours returns A; ours returns B", in seven digits, or in every digit where seven would write the two the
     * same: they are apart beyond the seventh (float arithmetic, say), and the reader must see them differ.
     */
    static String yoursAndOurs(Function<Digits, String> yours, Function<Digits, String> ours) {
        Digits digits = yours.apply(Digits.SEVEN).equals(ours.apply(Digits.SEVEN)) ? Digits.EVERY : Digits.SEVEN;
        return "yours returns " + yours.apply(digits) + "; ours returns " + ours.apply(digits);
    }

    static String ray(BehaviourInputs.IntersectionCall call) {
        return "the ray from O = " + vector(call.origin()) + " along D = " + vector(call.direction())
                + " and the sphere of centre C = " + vector(call.centre()) + " and radius r = " + number(call.radius());
    }

    static String shading(BehaviourInputs.IlluminationCall call, BehaviourInputs.Phong phong) {
        BehaviourInputs.LightInput light = call.light();
        BehaviourInputs.Material material = call.sphere().material();
        boolean course = phong == BehaviourInputs.Phong.FIXED || material.kD() == BehaviourInputs.COURSE_KD
                && material.kS() == BehaviourInputs.COURSE_KS
                && material.n() == BehaviourInputs.COURSE_N;
        String coefficients = course ? "" : ", k_d = " + number(material.kD()) + ", k_s = " + number(material.kS())
                + ", n = " + number(material.n());
        return "P = " + vector(call.point()) + ", N = " + vector(call.normal()) + " on a sphere of colour C_diff = "
                + vector(material.colour()) + coefficients + ", ambient light I_a = " + vector(call.ambient())
                + " and a point light at " + vector(light.position()) + " of colour " + vector(light.colour())
                + " and intensity " + intensity(light.intensity());
    }

    /** A hit, no hit, or how the call gave no answer. */
    static String hit(Answer answer) {
        return hit(answer, Digits.SEVEN);
    }

    /** As {@link #hit(Answer)}, each number in {@code digits}. */
    static String hit(Answer answer, Digits digits) {
        if (answer instanceof Hit hit) {
            return !hit.sameSphere() ? "a hit that names another sphere than this one"
                    : "a hit at s = " + number(hit.distance(), digits) + ", P = "
                    + vector(hit.point(), digits) + ", N = " + vector(hit.normal(), digits);
        }
        return answer instanceof Answers.None ? "no hit" : failure(answer);
    }

    static String hit(Models.Hit hit) {
        return hit(hit, Digits.SEVEN);
    }

    static String hit(Models.Hit hit, Digits digits) {
        return hit == null ? "no hit" : "a hit at s = " + number(hit.distance(), digits) + ", P = "
                + vector(new double[] {hit.point().x, hit.point().y, hit.point().z}, digits) + ", N = "
                + vector(new double[] {hit.normal().x, hit.normal().y, hit.normal().z}, digits);
    }

    static String colour(Answer answer) {
        return colour(answer, Digits.SEVEN);
    }

    static String colour(Answer answer, Digits digits) {
        return answer instanceof Colour colour ? "the colour " + vector(colour.rgb(), digits) : failure(answer);
    }

    static String colour(Vector3 colour) {
        return colour(colour, Digits.SEVEN);
    }

    static String colour(Vector3 colour, Digits digits) {
        return "the colour " + vector(new double[] {colour.x, colour.y, colour.z}, digits);
    }

    private static String failure(Answer answer) {
        String how = answer instanceof Failed failed ? failed.how() : "";
        return switch (how) {
            case "null" -> "null";
            case "threw" -> "an exception";
            case "timeout" -> "no answer within half a second";
            case "absent" -> "nothing: there is no illuminate(Scene, Sphere, Vector3, Vector3) returning a Vector3";
            default -> "no answer (the call did not return in time, or the run stopped before it)";
        };
    }

    private static String intensity(double intensity) {
        double k = intensity / (4 * Math.PI);
        if (intensity == 0) {
            return "0";
        }
        return k == Math.rint(k) ? (k == 1 ? "4 pi" : number(k) + " x 4 pi") : number(intensity);
    }

    static String vector(Vector3 v) {
        return vector(new double[] {v.x, v.y, v.z});
    }

    static String vector(double[] v) {
        return vector(v, Digits.SEVEN);
    }

    private static String vector(double[] v, Digits digits) {
        return "(" + number(v[0], digits) + ", " + number(v[1], digits) + ", " + number(v[2], digits) + ")";
    }

    /** The shortest decimal that reads back as {@code x}, or 7 significant digits for a long one. */
    static String number(double x) {
        return number(x, Digits.SEVEN);
    }

    /** As {@link #number(double)}; with {@link Digits#EVERY}, always the shortest decimal that reads back as x. */
    private static String number(double x, Digits digits) {
        if (Double.isNaN(x) || Double.isInfinite(x)) {
            return Double.toString(x);
        }
        if (x == Math.rint(x) && Math.abs(x) < 1e15) {
            return Long.toString((long) x);
        }
        String shortest = BigDecimal.valueOf(x).stripTrailingZeros().toPlainString();
        if (digits == Digits.EVERY || shortest.length() <= 10) {
            return shortest;
        }
        return new BigDecimal(x).round(new MathContext(7)).stripTrailingZeros().toPlainString();
    }

    /** How far from round an input's numbers are: their sizes, and more for each that is not in tenths. */
    static double roughness(double... numbers) {
        double rough = 0;
        for (double x : numbers) {
            rough += Math.abs(x) + (x * 10 == Math.rint(x * 10) ? 0 : 3) + (x == Math.rint(x) ? 0 : 0.5);
        }
        return rough;
    }

    static double roughness(BehaviourInputs.IntersectionCall call) {
        return roughness(concat(call.origin(), call.direction(), call.centre(), new double[] {call.radius()}));
    }

    static double roughness(BehaviourInputs.IlluminationCall call) {
        BehaviourInputs.LightInput light = call.light();
        BehaviourInputs.Material material = call.sphere().material();
        return roughness(concat(call.point(), call.normal(), material.colour(), call.ambient(), light.position(),
                light.colour(), new double[] {material.kD(), material.kS(), material.n() / 10,
                    light.intensity() / (4 * Math.PI)}));
    }

    private static double[] concat(double[]... parts) {
        int length = 0;
        for (double[] part : parts) {
            length += part.length;
        }
        double[] all = new double[length];
        int at = 0;
        for (double[] part : parts) {
            System.arraycopy(part, 0, all, at, part.length);
            at += part.length;
        }
        return all;
    }
}
