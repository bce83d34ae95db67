package gfx.tick1.command.shared.grader.lookalike;

import gfx.tick1.command.grade.StudentSolution;
import gfx.tick1.command.shared.kit.StarterKit;
import java.util.List;

/**
 * Correct solutions of the tick written independently, each in a style of its own, as a cohort's
 * honest students write them: the starter kit's two files with the TODOs of intersectionWith and
 * illuminate filled in, and sometimes a helper method added. They share only what the handout and
 * the starter code give everyone, and what correct code must say.
 */
final class Handwritten {

    /** A student's two files. */
    record Solution(String name, String sphere, String renderer) {

        @Override
        public String toString() {
            return name;
        }

        Solution sphere(String text, String replacement) {
            return new Solution(name, StudentSolution.replaceOnce(sphere, text, replacement), renderer);
        }

        Solution renderer(String text, String replacement) {
            return new Solution(name, sphere, StudentSolution.replaceOnce(renderer, text, replacement));
        }

        Solution named(String newName) {
            return new Solution(newName, sphere, renderer);
        }
    }

    private static final String SPHERE_TODO = "        // TODO: Determine if ray and sphere intersect";
    private static final String SPHERE_END = "        return new RaycastHit();\n    }";
    private static final String RENDERER_TODO = "        // TODO: Calculate L, V, and R";
    private static final String RENDERER_END = "        return object.getColour();\n    }";

    private Handwritten() {
    }

    /** The starter's files with the two methods' TODOs replaced by {@code intersection} and {@code illumination}. */
    static Solution of(String name, String intersection, String illumination, String sphereHelper,
            String rendererHelper) {
        return new Solution(name, fill(StarterKit.source("Sphere"), SPHERE_TODO, SPHERE_END, intersection,
                sphereHelper), fill(StarterKit.source("Renderer"), RENDERER_TODO, RENDERER_END, illumination,
                rendererHelper));
    }

    private static String fill(String starter, String todo, String end, String body, String helper) {
        int from = starter.indexOf(todo);
        int to = starter.indexOf(end, from) + end.length();
        String filled = starter.substring(0, from) + body.stripTrailing().indent(8) + "    }" + starter.substring(to);
        if (helper != null) {
            int last = filled.lastIndexOf('}');
            filled = filled.substring(0, last) + "\n" + helper.stripTrailing().indent(4) + "}\n";
        }
        return filled;
    }

    /** Six students, each with both methods in a style of their own. */
    static List<Solution> cohort() {
        return List.of(
                of("early returns", """
                        double discriminant = b * b - 4 * a * c;
                        if (discriminant < 0) {
                            return new RaycastHit();
                        }
                        double sqrtDisc = Math.sqrt(discriminant);
                        double near = (-b - sqrtDisc) / (2 * a);
                        if (near > 0) {
                            Vector3 point = ray.evaluateAt(near);
                            return new RaycastHit(this, near, point, getNormalAt(point));
                        }
                        double far = (-b + sqrtDisc) / (2 * a);
                        if (far > 0) {
                            Vector3 point = ray.evaluateAt(far);
                            return new RaycastHit(this, far, point, getNormalAt(point));
                        }
                        return new RaycastHit();
                        """, """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = new Vector3(0).subtract(P).normalised();
                        Vector3 R = L.reflectIn(N);
                        double NdotL = Math.max(0, N.dot(L));
                        double RdotV = Math.max(0, R.dot(V));
                        Vector3 colour = C_diff.scale(I_a);
                        colour = colour.add(C_diff.scale(I).scale(k_d * NdotL));
                        colour = colour.add(C_spec.scale(I).scale(k_s * Math.pow(RdotV, n)));
                        return colour;
                        """, null, null),
                of("min and max of the roots", """
                        double d = Math.pow(b, 2) - 4 * a * c;
                        if (d >= 0) {
                            double root1 = (-b + Math.sqrt(d)) / (2 * a);
                            double root2 = (-b - Math.sqrt(d)) / (2 * a);
                            double nearest = Math.min(root1, root2);
                            double furthest = Math.max(root1, root2);
                            if (nearest <= 0) {
                                nearest = furthest;
                            }
                            if (nearest > 0) {
                                Vector3 p = ray.evaluateAt(nearest);
                                return new RaycastHit(this, nearest, p, this.getNormalAt(p));
                            }
                        }
                        return new RaycastHit();
                        """, """
                        Vector3 toLight = light.getPosition().subtract(P).normalised();
                        Vector3 toCamera = P.scale(-1).normalised();
                        Vector3 reflected = toLight.reflectIn(N);
                        Vector3 ambient = C_diff.scale(I_a);
                        Vector3 diffuse = new Vector3(0);
                        double cosTheta = N.dot(toLight);
                        if (cosTheta > 0) {
                            diffuse = C_diff.scale(I).scale(k_d * cosTheta);
                        }
                        Vector3 specular = new Vector3(0);
                        double cosAlpha = reflected.dot(toCamera);
                        if (cosAlpha > 0) {
                            specular = C_spec.scale(I).scale(k_s * Math.pow(cosAlpha, n));
                        }
                        return ambient.add(diffuse).add(specular);
                        """, null, null),
                of("one root, then the other", """
                        double q = b * b - 4 * a * c;
                        if (q < 0) return new RaycastHit();
                        double s = (-b - Math.sqrt(q)) / (2 * a);
                        if (s <= 0) s = (-b + Math.sqrt(q)) / (2 * a);
                        if (s <= 0) return new RaycastHit();
                        Vector3 at = ray.evaluateAt(s);
                        Vector3 normal = getNormalAt(at);
                        return new RaycastHit(this, s, at, normal);
                        """, """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        return C_diff.scale(I_a)
                                .add(C_diff.scale(I).scale(k_d * Math.max(0.0, N.dot(L))))
                                .add(C_spec.scale(I).scale(k_s * Math.pow(Math.max(0.0, R.dot(V)), n)));
                        """, null, null),
                of("a helper for the nearest positive root", """
                        double disc = b * b - 4 * a * c;
                        if (disc < 0) {
                            return new RaycastHit();
                        }
                        double t = nearestPositive((-b - Math.sqrt(disc)) / (2 * a), (-b + Math.sqrt(disc)) / (2 * a));
                        if (Double.isNaN(t)) {
                            return new RaycastHit();
                        }
                        Vector3 hitPoint = O.add(D.scale(t));
                        return new RaycastHit(this, t, hitPoint, getNormalAt(hitPoint));
                        """, """
                        Vector3 lightDir = light.getPosition().subtract(P).normalised();
                        Vector3 viewDir = P.scale(-1.0).normalised();
                        Vector3 reflectDir = N.scale(2 * N.dot(lightDir)).subtract(lightDir);
                        double diffuseFactor = clamp(N.dot(lightDir));
                        double specularFactor = Math.pow(clamp(reflectDir.dot(viewDir)), n);
                        Vector3 result = C_diff.scale(I_a);
                        result = result.add(C_diff.scale(I).scale(k_d).scale(diffuseFactor));
                        result = result.add(C_spec.scale(I).scale(k_s).scale(specularFactor));
                        return result;
                        """, """
                        // The smaller of two roots that is positive, or NaN when neither is
                        private static double nearestPositive(double first, double second) {
                            if (first > 0) {
                                return first;
                            }
                            return second > 0 ? second : Double.NaN;
                        }
                        """, """
                        private static double clamp(double value) {
                            return value < 0 ? 0 : value;
                        }
                        """),
                of("if, else if, else", """
                        double delta = b * b - 4 * a * c;
                        double t;
                        if (delta < 0) {
                            return new RaycastHit();
                        } else {
                            double t1 = (-b - Math.sqrt(delta)) / (2 * a);
                            double t2 = (-b + Math.sqrt(delta)) / (2 * a);
                            if (t1 > 0) {
                                t = t1;
                            } else if (t2 > 0) {
                                t = t2;
                            } else {
                                return new RaycastHit();
                            }
                        }
                        Vector3 position = ray.evaluateAt(t);
                        Vector3 normal = this.getNormalAt(position);
                        RaycastHit hit = new RaycastHit(this, t, position, normal);
                        return hit;
                        """, """
                        Vector3 L = light.getPosition().subtract(P);
                        L = L.normalised();
                        Vector3 V = P.scale(-1);
                        V = V.normalised();
                        Vector3 R = L.reflectIn(N);
                        double NdotL = N.dot(L);
                        double RdotV = R.dot(V);
                        if (NdotL < 0) NdotL = 0;
                        if (RdotV < 0) RdotV = 0;
                        Vector3 ambient = I_a.scale(C_diff);
                        Vector3 diffuse = I.scale(C_diff).scale(k_d).scale(NdotL);
                        Vector3 specular = I.scale(C_spec).scale(k_s).scale(Math.pow(RdotV, n));
                        return ambient.add(diffuse.add(specular));
                        """, null, null),
                of("the half-b formula", """
                        double halfB = b / 2;
                        double quarterDisc = halfB * halfB - a * c;
                        if (quarterDisc < 0) {
                            return new RaycastHit();
                        }
                        double root = Math.sqrt(quarterDisc);
                        double s = (-halfB - root) / a;
                        if (s <= 0) {
                            s = (-halfB + root) / a;
                        }
                        if (s > 0) {
                            Vector3 p = ray.evaluateAt(s);
                            return new RaycastHit(this, s, p, getNormalAt(p));
                        }
                        return new RaycastHit();
                        """, """
                        Vector3 L = light.getPosition().subtract(P).normalised();
                        Vector3 V = P.scale(-1).normalised();
                        Vector3 R = L.reflectIn(N);
                        Vector3 ambient = C_diff.scale(I_a);
                        Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, N.dot(L)));
                        Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, R.dot(V)), n));
                        return ambient.add(diffuse).add(specular);
                        """, null, null));
    }
}
