package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.grade.StudentSolution;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Seventeen correct solutions in styles of their own, each written here as an edit of the body
 * of intersectionWith or of illuminate in the correct solution of the test resources: other root
 * formulas (the stable one, the geometric one, half b, the handout's six steps to the letter),
 * other orders and groupings of the Phong terms, clamps written every way, a colour clamped to
 * [0, 1] before it is returned. Every one of them renders the course's images and behaves as ours.
 */
public final class WrittenStyles {

    /** A style's name and its two files. */
    public record Style(String name, String sphere, String renderer) {
        @Override
        public String toString() {
            return name;
        }
    }

    private static final String INTERSECTION_FROM = "        // A negative discriminant";
    private static final String INTERSECTION_TO =
            "        // Currently returning empty RaycastHit for no intersection\n        return new RaycastHit();\n";
    private static final String SHADING_FROM = "        // L and V, unit vectors";
    private static final String SHADING_TO = "return ambient.add(diffuse).add(specular);\n";

    private WrittenStyles() {
    }

    /** The styles by name, in the order written. */
    public static Map<String, Style> all() {
        Map<String, Style> styles = new LinkedHashMap<>();
        intersections(styles);
        shadings(styles);
        return styles;
    }

    private static void intersections(Map<String, Style> styles) {
        sphere(styles, "the stable quadratic formula", """
                        double disc = b * b - 4 * a * c;
                        if (disc < 0) {
                            return new RaycastHit();
                        }
                        double q = -0.5 * (b + Math.copySign(Math.sqrt(disc), b));
                        double r1 = q / a, r2 = c / q;
                        double near = Math.min(r1, r2), far = Math.max(r1, r2);
                        double s = near > 0 ? near : far;
                        if (!(s > 0)) {
                            return new RaycastHit();
                        }
                        Vector3 point = ray.evaluateAt(s);
                        return new RaycastHit(this, s, point, getNormalAt(point));
                """);
        sphere(styles, "the geometric method", """
                        Vector3 toCentre = C.subtract(O);
                        double along = toCentre.dot(D) / a;
                        double apart = toCentre.dot(toCentre) - along * along * a;
                        if (apart > r * r) {
                            return new RaycastHit();
                        }
                        double half = Math.sqrt((r * r - apart) / a);
                        double s = along - half > 0 ? along - half : along + half;
                        if (s <= 0) {
                            return new RaycastHit();
                        }
                        Vector3 point = O.add(D.scale(s));
                        return new RaycastHit(this, s, point, point.subtract(C).normalised());
                """);
        sphere(styles, "min and max of the roots", """
                        double disc = b * b - 4 * a * c;
                        if (disc >= 0) {
                            double lo = Math.min((-b - Math.sqrt(disc)) / (2 * a), (-b + Math.sqrt(disc)) / (2 * a));
                            double hi = Math.max((-b - Math.sqrt(disc)) / (2 * a), (-b + Math.sqrt(disc)) / (2 * a));
                            double s = lo > 0 ? lo : hi;
                            if (s > 0) {
                                Vector3 at = ray.evaluateAt(s);
                                return new RaycastHit(this, s, at, this.getNormalAt(at));
                            }
                        }
                        return new RaycastHit();
                """);
        sphere(styles, "the normal scaled by 1 / r", """
                        double disc = b * b - 4 * a * c;
                        if (disc < 0) {
                            return new RaycastHit();
                        }
                        double s = (-b - Math.sqrt(disc)) / (2 * a);
                        if (s <= 0) {
                            s = (-b + Math.sqrt(disc)) / (2 * a);
                        }
                        if (s <= 0) {
                            return new RaycastHit();
                        }
                        Vector3 point = ray.evaluateAt(s);
                        return new RaycastHit(this, s, point, point.subtract(C).scale(1 / r));
                """);
        sphere(styles, "no hit for a zero discriminant", """
                        double disc = b * b - 4 * a * c;
                        if (disc <= 0) {
                            return new RaycastHit();
                        }
                        double s1 = (-b - Math.sqrt(disc)) / (2 * a), s2 = (-b + Math.sqrt(disc)) / (2 * a);
                        double s = s1 > 0 ? s1 : s2;
                        if (s > 0) {
                            Vector3 point = ray.evaluateAt(s);
                            return new RaycastHit(this, s, point, getNormalAt(point));
                        }
                        return new RaycastHit();
                """);
        sphere(styles, "the handout's six steps to the letter", """
                        double disc = b * b - 4 * a * c;
                        if (disc < 0) {
                            return new RaycastHit();
                        }
                        double s1 = (-b - Math.sqrt(disc)) / (2 * a);
                        double s2 = (-b + Math.sqrt(disc)) / (2 * a);
                        if (s1 > 0 && s1 < s2) {
                            Vector3 point = ray.evaluateAt(s1);
                            return new RaycastHit(this, s1, point, getNormalAt(point));
                        } else if (s2 > 0 && s2 < s1) {
                            Vector3 point = ray.evaluateAt(s2);
                            return new RaycastHit(this, s2, point, getNormalAt(point));
                        }
                        return new RaycastHit();
                """);
        sphere(styles, "the direction normalised first", """
                        double length = Math.sqrt(a);
                        Vector3 unit = D.scale(1 / length);
                        double h = unit.dot(O.subtract(C));
                        double disc = h * h - (O.subtract(C).dot(O.subtract(C)) - r * r);
                        if (disc < 0) {
                            return new RaycastHit();
                        }
                        double t = -h - Math.sqrt(disc) > 0 ? -h - Math.sqrt(disc) : -h + Math.sqrt(disc);
                        if (t <= 0) {
                            return new RaycastHit();
                        }
                        double s = t / length;
                        Vector3 point = O.add(unit.scale(t));
                        return new RaycastHit(this, s, point, getNormalAt(point));
                """);
    }

    private static void shadings(Map<String, Style> styles) {
        renderer(styles, "the colour clamped to [0, 1] before it is returned", """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        double NdotL = N.dot(L);
                        double RdotV = R.dot(V);
                        Vector3 ambient = C_diff.scale(I_a);
                        Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, NdotL));
                        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, RdotV), n));
                        Vector3 sum = ambient.add(diffuse).add(specular);
                        return new Vector3(Math.min(1, Math.max(0, sum.x)), Math.min(1, Math.max(0, sum.y)),
                                Math.min(1, Math.max(0, sum.z)));
                """);
        renderer(styles, "channel by channel", """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        double kd = k_d * Math.max(0, N.dot(L));
                        double ks = k_s * Math.pow(Math.max(0, R.dot(V)), n);
                        double red = C_diff.x * I_a.x + C_diff.x * I.x * kd + C_spec.x * I.x * ks;
                        double green = C_diff.y * I_a.y + C_diff.y * I.y * kd + C_spec.y * I.y * ks;
                        double blue = C_diff.z * I_a.z + C_diff.z * I.z * kd + C_spec.z * I.z * ks;
                        return new Vector3(red, green, blue);
                """);
        renderer(styles, "ternaries for the clamps, R written out", """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        double NdotL = N.dot(L);
                        Vector3 R = N.scale(2 * NdotL).subtract(L);
                        Vector3 V = new Vector3(-P.x, -P.y, -P.z).normalised();
                        double RdotV = R.dot(V);
                        double cosine = NdotL > 0 ? NdotL : 0;
                        double highlight = RdotV > 0 ? Math.pow(RdotV, n) : 0;
                        Vector3 ambient = C_diff.scale(I_a);
                        return ambient.add(C_diff.scale(I).scale(k_d * cosine)).add(I.scale(k_s * highlight));
                """);
        renderer(styles, "I computed by hand", """
                        Vector3 toLight = light.getPosition().subtract(P);
                        double d = toLight.magnitude();
                        Vector3 light_I = light.getColour().scale(light.getIntensity() / (4 * Math.PI * d * d));
                        Vector3 L = toLight.scale(1 / d);
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        Vector3 ambient = C_diff.scale(I_a);
                        Vector3 diffuse = C_diff.scale(light_I).scale(k_d * Math.max(0, N.dot(L)));
                        Vector3 specular = C_spec.scale(light_I).scale(k_s * Math.pow(Math.max(0, R.dot(V)), n));
                        return ambient.add(diffuse).add(specular);
                """);
        renderer(styles, "the two lit terms grouped under I", """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        Vector3 lit = C_diff.scale(k_d * Math.max(0, N.dot(L)))
                                .add(C_spec.scale(k_s * Math.pow(Math.max(0, R.dot(V)), n)));
                        return lit.scale(I).add(I_a.scale(C_diff));
                """);
        renderer(styles, "an early return where the light is behind", """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 ambient = C_diff.scale(I_a);
                        double NdotL = N.dot(L);
                        Vector3 R = L.reflectIn(N);
                        double RdotV = Math.max(0, R.dot(V));
                        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(RdotV, n));
                        if (NdotL <= 0) {
                            return ambient.add(specular);
                        }
                        return ambient.add(C_diff.scale(I).scale(k_d * NdotL)).add(specular);
                """);
        renderer(styles, "the terms summed into a new Vector3", """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        Vector3 a = C_diff.scale(I_a);
                        Vector3 d = C_diff.scale(I).scale(k_d * Math.max(0, N.dot(L)));
                        Vector3 s = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, R.dot(V)), n));
                        return new Vector3(a.x + d.x + s.x, a.y + d.y + s.y, a.z + d.z + s.z);
                """);
        renderer(styles, "the specular first and scaled last", """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        double spec = Math.pow(Math.max(0.0, R.dot(V)), n);
                        Vector3 specular = I.scale(C_spec).scale(spec).scale(k_s);
                        Vector3 diffuse = I.scale(C_diff).scale(Math.max(0.0, L.dot(N))).scale(k_d);
                        return specular.add(diffuse).add(C_diff.scale(I_a));
                """);
        renderer(styles, "the light vector reversed twice", """
                        Vector3 fromLight = P.subtract(light.getPosition()).normalised();
                        Vector3 L = fromLight.scale(-1);
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        Vector3 ambient = C_diff.scale(I_a);
                        Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, -N.dot(fromLight)));
                        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, R.dot(V)), n));
                        return ambient.add(diffuse).add(specular);
                """);
        renderer(styles, "the camera's direction from the origin", """
                        Vector3 camera = new Vector3(0, 0, 0);
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = camera.subtract(P).normalised();
                        Vector3 R = L.reflectIn(N);
                        double NdotL = Math.max(N.dot(L), 0);
                        double RdotV = Math.max(R.dot(V), 0);
                        return C_diff.scale(I_a).add(C_diff.scale(I).scale(k_d).scale(NdotL))
                                .add(C_spec.scale(I).scale(k_s).scale(Math.pow(RdotV, n)));
                """);
    }

    private static void sphere(Map<String, Style> styles, String name, String body) {
        String correct = StudentSolution.resource("Sphere.java");
        styles.put(name, new Style(name, between(correct, INTERSECTION_FROM, INTERSECTION_TO, body),
                StudentSolution.resource("Renderer.java")));
    }

    private static void renderer(Map<String, Style> styles, String name, String body) {
        String correct = StudentSolution.resource("Renderer.java");
        styles.put(name, new Style(name, StudentSolution.resource("Sphere.java"),
                between(correct, SHADING_FROM, SHADING_TO, body)));
    }

    private static String between(String source, String from, String to, String body) {
        int start = source.indexOf(from), end = source.indexOf(to);
        if (start < 0 || end < start) {
            throw new IllegalArgumentException("the correct solution's text is not where the styles expect it");
        }
        return source.substring(0, start) + body + source.substring(end + to.length());
    }
}
