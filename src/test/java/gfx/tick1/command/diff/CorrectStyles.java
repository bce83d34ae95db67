package gfx.tick1.command.diff;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

/**
 * Correct solutions of the tick written in other styles than ours, each as edits of the correct
 * solution in {@code src/test/resources/students/correct}: the ones that differ from it only in
 * layout (names, {@code this.}, parentheses, the order of independent declarations), and the ones
 * that compute the same image another way. Every edit must find its text exactly once.
 */
public final class CorrectStyles {

    /** A correct solution: its two files and the members whose syntax differs from ours. */
    public record Style(String name, String sphere, String renderer, Set<String> changedMembers) {

        @Override
        public String toString() {
            return name;
        }

        Style sphere(String text, String replacement) {
            return new Style(name, replaceOnce(sphere, text, replacement), renderer, changedMembers);
        }

        /** Every whole-word {@code name} in Sphere.java renamed {@code to}. */
        Style sphereRenamed(String name, String to) {
            if (!sphere.matches("(?s).*\\b" + name + "\\b.*")) {
                throw new IllegalArgumentException(name + " is not in Sphere.java");
            }
            return new Style(this.name, sphere.replaceAll("\\b" + name + "\\b", to), renderer, changedMembers);
        }

        /** The method of Sphere.java that {@code header} opens, from it to its closing brace, as {@code method}. */
        Style sphereMethod(String header, String method) {
            return new Style(name, replaceMethod(sphere, header, method), renderer, changedMembers);
        }

        /** The method of Renderer.java that {@code header} opens, from it to its closing brace, as {@code method}. */
        Style rendererMethod(String header, String method) {
            return new Style(name, sphere, replaceMethod(renderer, header, method), changedMembers);
        }

        /** Every line of the two files that {@code edit} changes, as it changes it. */
        Style eachLine(java.util.function.UnaryOperator<String> edit) {
            return new Style(name, eachLine(sphere, edit), eachLine(renderer, edit), changedMembers);
        }

        private static String eachLine(String source, java.util.function.UnaryOperator<String> edit) {
            return source.lines().map(edit).collect(java.util.stream.Collectors.joining("\n", "", "\n"));
        }

        Style renderer(String text, String replacement) {
            return new Style(name, sphere, replaceOnce(renderer, text, replacement), changedMembers);
        }

        /** Writes Sphere.java and Renderer.java into {@code folder}. */
        public Path[] writeTo(Path folder) throws IOException {
            Files.createDirectories(folder);
            Path s = folder.resolve("Sphere.java"), r = folder.resolve("Renderer.java");
            Files.writeString(s, sphere);
            Files.writeString(r, renderer);
            return new Path[] {s, r};
        }
    }

    public static final String INTERSECTION = "intersectionWith(Ray)";
    public static final String ILLUMINATE = "illuminate(Scene, Sphere, Vector3, Vector3)";

    private static final String L = "Vector3 L = light.getPosition().subtract(P).normalised();";
    private static final String V = "Vector3 V = P.scale(-1).normalised();";
    private static final String AMBIENT = "Vector3 ambient = C_diff.scale(I_a);";
    private static final String DIFFUSE = "Vector3 diffuse = C_diff.scale(I).scale(k_d * Math.max(0, NdotL));";
    private static final String SPECULAR =
            "Vector3 specular = C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, RdotV), n));";
    private static final String DISTANCE = "double distanceToLight = light.getPosition().subtract(P).magnitude();";
    private static final String I_A = "Vector3 I_a = scene.getAmbientLighting();";
    private static final String ILLUMINATE_HEADER =
            "private Vector3 illuminate(Scene scene, Sphere object, Vector3 P, Vector3 N) {";

    private CorrectStyles() {
    }

    /** Statements one after another at the indent of a method's body. */
    private static String lines(String... statements) {
        return String.join("\n        ", statements);
    }

    private static Style correct(String name, String... changedMembers) {
        return new Style(name, resource("Sphere.java"), resource("Renderer.java"), Set.of(changedMembers));
    }

    /** Solutions that differ from ours only in what cannot change the meaning: diff exits 0 on them. */
    public static List<Style> layoutOnly() {
        return List.of(
                correct("renamed locals").sphereRenamed("discriminant", "disc").sphereRenamed("s1", "near")
                        .sphereRenamed("s2", "far").sphere("Vector3 point", "Vector3 hitPoint")
                        .sphere("getNormalAt(point)", "getNormalAt(hitPoint)")
                        .sphere("new RaycastHit(this, s, point, normal)", "new RaycastHit(this, s, hitPoint, normal)")
                        .renderer("Vector3 linearRGB = trace(scene, ray);", "Vector3 pixel = trace(scene, ray);")
                        .renderer("linearRGB.toRGB()", "pixel.toRGB()"),
                correct("the two roots' names exchanged").sphereRenamed("s1", "swapped").sphereRenamed("s2", "s1")
                        .sphereRenamed("swapped", "s2"),
                correct("renamed parameters")
                        .renderer("illuminate(Scene scene, Sphere object, Vector3 P, Vector3 N) {",
                                "illuminate(Scene world, Sphere object, Vector3 P, Vector3 N) {")
                        .renderer("light = scene.getPointLight();", "light = world.getPointLight();")
                        .renderer("I_a = scene.getAmbientLighting();", "I_a = world.getAmbientLighting();")
                        .renderer("public Renderer(int width, int height) {", "public Renderer(int w, int h) {")
                        .renderer("this.width = width;", "width = w;").renderer("this.height = height;", "height = h;")
                        .sphere("public Sphere(Vector3 position, double radius, Vector3 colour) {",
                                "public Sphere(Vector3 centre, double r, Vector3 colour) {")
                        .sphere("this.position = position;", "position = centre;")
                        .sphere("this.radius = radius;", "radius = r;"),
                correct("this. on every field")
                        .sphere("Vector3 C = position;", "Vector3 C = this.position;")
                        .sphere("double r = radius;", "double r = this.radius;")
                        .sphere("phong_kD = SPHERE_KD;", "this.phong_kD = this.SPHERE_KD;")
                        .sphere("public Vector3 getColour() { return colour; }",
                                "public Vector3 getColour() { return this.colour; }")
                        .renderer("return BACKGROUND_COLOUR;", "return this.BACKGROUND_COLOUR;"),
                correct("parentheses that change nothing")
                        .sphere("double b = 2 * D.dot(O.subtract(C));", "double b = (2 * (D.dot(O.subtract(C))));")
                        .sphere("discriminant = b * b - 4 * a * c;", "discriminant = (b * b) - (4 * a * c);")
                        .renderer("return ambient.add(diffuse).add(specular);",
                                "return (ambient.add(diffuse)).add((specular));")
                        .renderer("k_d * Math.max(0, NdotL)", "(k_d) * (Math.max(0, NdotL))"),
                correct("independent declarations in another order")
                        .renderer(lines(L, V), lines(V, L))
                        .renderer(lines("double NdotL = N.dot(L);", "double RdotV = R.dot(V);"),
                                lines("double RdotV = R.dot(V);", "double NdotL = N.dot(L);"))
                        .renderer(lines(AMBIENT, DIFFUSE, SPECULAR), lines(SPECULAR, AMBIENT, DIFFUSE))
                        .renderer(I_A, "").renderer(DISTANCE, lines(I_A, DISTANCE)),
                correct("final on every local and parameter of the two methods")
                        .eachLine(line -> line.matches(" {8,}(Vector3|double|PointLight) \\w+ = .*")
                                ? line.replaceFirst("^( +)", "$1final ") : line)
                        .sphere("intersectionWith(Ray ray)", "intersectionWith(final Ray ray)")
                        .renderer("illuminate(Scene scene, Sphere object, Vector3 P, Vector3 N)",
                                "illuminate(final Scene scene, final Sphere object, final Vector3 P, final Vector3 N)"),
                correct("annotated and final locals under other names")
                        .sphereRenamed("discriminant", "delta")
                        .sphere("double s = s1 > 0 ? s1 : s2;", "@SuppressWarnings(\"unused\") final double t = s1 > 0 "
                                + "? s1 : s2;")
                        .sphere("if (s > 0) {", "if (t > 0) {").sphere("ray.evaluateAt(s);", "ray.evaluateAt(t);")
                        .sphere("new RaycastHit(this, s, point", "new RaycastHit(this, t, point")
                        .renderer("Vector3 R = L.reflectIn(N);", "final Vector3 mirrored = L.reflectIn(N);")
                        .renderer("double RdotV = R.dot(V);", "double RdotV = mirrored.dot(V);"),
                correct("the starter code's own layout: this.phong_kD and a pixel")
                        .sphere("phong_kD = SPHERE_KD;", "this.phong_kD = SPHERE_KD;")
                        .sphere("phong_kS = SPHERE_KS;", "this.phong_kS = SPHERE_KS;")
                        .sphere("phong_n = SPHERE_N;", "this.phong_n = SPHERE_N;")
                        .renderer("Vector3 linearRGB = trace(scene, ray);", "Vector3 pixel = trace(scene, ray);")
                        .renderer("linearRGB.toRGB()", "pixel.toRGB()"));
    }

    /**
     * Solutions that draw the same image as ours by other code: diff shows the members they
     * change, and only those.
     */
    public static List<Style> otherCode() {
        return List.of(
                correct("if/else for the ternary", INTERSECTION).sphere("double s = s1 > 0 ? s1 : s2;",
                        lines("double s;", "if (s1 > 0) {", "    s = s1;", "} else {", "    s = s2;", "}")),
                correct("the clamp moved into NdotL", ILLUMINATE)
                        .renderer("double NdotL = N.dot(L);", "double NdotL = Math.max(0, N.dot(L));")
                        .renderer("k_d * Math.max(0, NdotL)", "k_d * NdotL"),
                correct("the clamps moved into both cosines", ILLUMINATE)
                        .renderer("double NdotL = N.dot(L);", "double NdotL = Math.max(0.0, N.dot(L));")
                        .renderer("double RdotV = R.dot(V);", "double RdotV = Math.max(R.dot(V), 0.0);")
                        .renderer("k_d * Math.max(0, NdotL)", "k_d * NdotL")
                        .renderer("Math.pow(Math.max(0, RdotV), n)", "Math.pow(RdotV, n)"),
                correct("split roots", INTERSECTION)
                        .sphere("double s1 = (-b - Math.sqrt(discriminant)) / (2 * a);",
                                lines("double root = Math.sqrt(discriminant);", "double s1 = (-b - root) / (2 * a);"))
                        .sphere("double s2 = (-b + Math.sqrt(discriminant)) / (2 * a);",
                                "double s2 = (-b + root) / (2 * a);"),
                correct("an early return for each root", INTERSECTION)
                        .sphere("double s = s1 > 0 ? s1 : s2;", lines("if (s1 > 0) {",
                                "    return new RaycastHit(this, s1, ray.evaluateAt(s1),",
                                "            getNormalAt(ray.evaluateAt(s1)));",
                                "}", "double s = s2;")),
                correct("extra normalisations", ILLUMINATE)
                        .renderer("Vector3 R = L.reflectIn(N);",
                                "Vector3 R = L.reflectIn(N.normalised()).normalised();"),
                correct("half b: s = (-b' -+ sqrt(b'^2 - a c)) / a", INTERSECTION)
                        .sphereMethod("public RaycastHit intersectionWith(Ray ray) {", lines(
                                "public RaycastHit intersectionWith(Ray ray) {",
                                "    Vector3 toOrigin = ray.getOrigin().subtract(position);",
                                "    Vector3 direction = ray.getDirection();",
                                "    double a = direction.dot(direction);",
                                "    double halfB = direction.dot(toOrigin);",
                                "    double c = toOrigin.dot(toOrigin) - radius * radius;",
                                "    double quarterDiscriminant = halfB * halfB - a * c;",
                                "    if (quarterDiscriminant < 0) {",
                                "        return new RaycastHit();",
                                "    }",
                                "    double root = Math.sqrt(quarterDiscriminant);",
                                "    double near = (-halfB - root) / a;",
                                "    double far = (-halfB + root) / a;",
                                "    double s = near > 0 ? near : far;",
                                "    if (s <= 0) {",
                                "        return new RaycastHit();",
                                "    }",
                                "    Vector3 point = ray.evaluateAt(s);",
                                "    return new RaycastHit(this, s, point, getNormalAt(point));",
                                "}")),
                correct("the roots tried in a loop, declarations shared", INTERSECTION)
                        .sphereMethod("public RaycastHit intersectionWith(Ray ray) {", lines(
                                "public RaycastHit intersectionWith(Ray ray) {",
                                "    Vector3 O = ray.getOrigin(), D = ray.getDirection(), OC = O.subtract(position);",
                                "    double a = D.dot(D), b = 2 * D.dot(OC), c = OC.dot(OC) - radius * radius;",
                                "    double disc = b * b - 4 * a * c;",
                                "    if (disc >= 0) {",
                                "        double sqrtDisc = Math.sqrt(disc);",
                                "        double[] roots = {(-b - sqrtDisc) / (2 * a), (-b + sqrtDisc) / (2 * a)};",
                                "        for (double s : roots) {",
                                "            if (s > 0) {",
                                "                Vector3 P = ray.evaluateAt(s);",
                                "                return new RaycastHit(this, s, P, getNormalAt(P));",
                                "            }",
                                "        }",
                                "    }",
                                "    return new RaycastHit();",
                                "}")),
                correct("a helper method makes the hit", INTERSECTION, "hitAt(Ray, double)")
                        .sphere(lines("if (s > 0) {", "    Vector3 point = ray.evaluateAt(s);",
                                "    Vector3 normal = this.getNormalAt(point);",
                                "    return new RaycastHit(this, s, point, normal);", "}"),
                                lines("if (s > 0) {", "    return hitAt(ray, s);", "}"))
                        .sphere("    public Vector3 getColour()", "    private RaycastHit hitAt(Ray ray, double s) {\n"
                                + "        Vector3 point = ray.evaluateAt(s);\n"
                                + "        return new RaycastHit(this, s, point, getNormalAt(point));\n"
                                + "    }\n\n    public Vector3 getColour()"),
                correct("terms added to one colour only where lit", ILLUMINATE)
                        .rendererMethod(ILLUMINATE_HEADER, lines(ILLUMINATE_HEADER,
                                "    PointLight light = scene.getPointLight();",
                                "    Vector3 toLight = light.getPosition().subtract(P);",
                                "    Vector3 I = light.getIlluminationAt(toLight.magnitude());",
                                "    Vector3 colour = object.getColour().scale(scene.getAmbientLighting());",
                                "    Vector3 L = toLight.normalised();",
                                "    double cosine = N.dot(L);",
                                "    if (cosine > 0) {",
                                "        colour = colour.add(object.getColour().scale(I).scale(object.getPhong_kD() "
                                        + "* cosine));",
                                "    }",
                                "    Vector3 R = L.reflectIn(N);",
                                "    double highlight = R.dot(P.scale(-1).normalised());",
                                "    if (highlight > 0) {",
                                "        colour = colour.add(I.scale(object.getPhong_kS() * Math.pow(highlight, "
                                        + "object.getPhong_n())));",
                                "    }",
                                "    return colour;",
                                "}")),
                correct("a clamp by if, and R written out as 2 (N.L) N - L", ILLUMINATE)
                        .renderer("Vector3 R = L.reflectIn(N);", "Vector3 R = N.scale(2 * N.dot(L)).subtract(L);")
                        .renderer("double NdotL = N.dot(L);",
                                lines("double NdotL = N.dot(L);", "if (NdotL < 0) {", "    NdotL = 0;", "}"))
                        .renderer("k_d * Math.max(0, NdotL)", "k_d * NdotL"),
                correct("the three terms in one return", ILLUMINATE)
                        .renderer(lines(AMBIENT, DIFFUSE, SPECULAR) + "\n\n        // Their sum\n"
                                + "        return ambient.add(diffuse).add(specular);",
                                lines("return C_diff.scale(I_a)",
                                "        .add(C_diff.scale(I).scale(k_d * Math.max(0, NdotL)))",
                                "        .add(C_spec.scale(I).scale(k_s * Math.pow(Math.max(0, RdotV), n)));")));
    }

    static String resource(String name) {
        try {
            return Files.readString(Path.of("src/test/resources/students/correct").resolve(name));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String replaceMethod(String source, String header, String method) {
        int start = source.indexOf(header);
        int end = source.indexOf("\n    }\n", start);
        if (start < 0 || source.indexOf(header, start + 1) >= 0 || end < 0) {
            throw new IllegalArgumentException("the method must be in the file exactly once: " + header);
        }
        return source.substring(0, start) + method.strip() + source.substring(end + "\n    }".length());
    }

    private static String replaceOnce(String source, String text, String replacement) {
        int at = source.indexOf(text);
        if (at < 0 || source.indexOf(text, at + 1) >= 0) {
            throw new IllegalArgumentException("the edit's text must be in the file exactly once: " + text);
        }
        return source.substring(0, at) + replacement + source.substring(at + text.length());
    }
}
