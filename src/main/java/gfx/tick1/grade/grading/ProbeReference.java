package gfx.tick1.grade.grading;

import gfx.tick1.grade.harness.ProbeCalls;

/**
 * What the reference answers on each of {@link ProbeCalls}, by the rules of the tick written out
 * in plain doubles: the hit is the nearest root with s &gt; 0, and the colour is C_diff I_a +
 * C_diff k_d I max(0, N.L) + C_spec k_s I max(0, R.V)^n with I = colour intensity / (4 pi d^2),
 * L = normalise(L_pos - P), V = normalise(-P), R = 2 (L.N) N - L, k_d = k_s = 0.8, n = 10.
 */
final class ProbeReference {

    static final double K_D = 0.8, K_S = 0.8, N = 10;

    private ProbeReference() {
    }

    /** The three terms of the colour at a call, each a colour. */
    record Terms(double[] ambient, double[] diffuse, double[] specular) {
        double[] sum() {
            return add(add(ambient, diffuse), specular);
        }
    }

    /** The distance of the hit, or infinity for none. */
    static double distance(ProbeCalls.Intersection call) {
        double[] oc = subtract(call.origin(), call.centre());
        double a = dot(call.direction(), call.direction());
        double b = 2 * dot(call.direction(), oc);
        double c = dot(oc, oc) - call.radius() * call.radius();
        double discriminant = b * b - 4 * a * c;
        if (discriminant < 0) {
            return Double.POSITIVE_INFINITY;
        }
        double s1 = (-b - Math.sqrt(discriminant)) / (2 * a), s2 = (-b + Math.sqrt(discriminant)) / (2 * a);
        double s = s1 > 0 ? s1 : s2;
        return s > 0 ? s : Double.POSITIVE_INFINITY;
    }

    static Terms terms(ProbeCalls.Illumination call) {
        double[] toLight = subtract(call.light(), call.point());
        double d = Math.sqrt(dot(toLight, toLight));
        double[] intensity = scale(call.lightColour(), call.intensity() / (4 * Math.PI * d * d));
        double[] l = scale(toLight, 1 / d);
        double[] v = scale(call.point(), -1 / Math.sqrt(dot(call.point(), call.point())));
        double[] n = call.normal();
        double[] r = subtract(scale(n, 2 * dot(l, n)), l);
        double[] ambient = times(call.colour(), call.ambient());
        double[] diffuse = scale(times(call.colour(), intensity), K_D * Math.max(0, dot(n, l)));
        double[] specular = scale(intensity, K_S * Math.pow(Math.max(0, dot(r, v)), N));
        return new Terms(ambient, diffuse, specular);
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] subtract(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    static double[] add(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    static double[] scale(double[] a, double k) {
        return new double[] {a[0] * k, a[1] * k, a[2] * k};
    }

    static double[] times(double[] a, double[] b) {
        return new double[] {a[0] * b[0], a[1] * b[1], a[2] * b[2]};
    }
}
