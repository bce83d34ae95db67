package gfx.tick1.command.preview;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.util.Base64;
import java.util.List;
import java.util.StringJoiner;

/**
 * What the previewer's page is told about a scene, as JSON, in the tick's own left-handed
 * coordinates (the page converts them for three.js). Colours go as {@code #RRGGBB}: the loader
 * made each channel value / 255.0, so rounding back gives the file's own digits.
 * A few lines by hand rather than a JSON library: the shapes are fixed and small.
 */
final class SceneJson {

    private SceneJson() {
    }

    /** {@code {"name", "warnings", "ambient", "light" (or null), "spheres"}}. */
    static String describe(String name, Scene scene, List<String> warnings) {
        StringJoiner spheres = new StringJoiner(",", "[", "]");
        for (Sphere sphere : scene.getObjects()) {
            spheres.add("{\"position\":" + vector(SphereGeometry.centre(sphere))
                    + ",\"radius\":" + SphereGeometry.radius(sphere)
                    + ",\"colour\":" + colour(sphere.getColour()) + "}");
        }
        PointLight light = scene.getPointLight();
        String lightJson = light == null ? "null"
                : "{\"position\":" + vector(light.getPosition()) + ",\"colour\":" + colour(light.getColour())
                        + ",\"intensity\":" + light.getIntensity() + "}";
        StringJoiner warningsJson = new StringJoiner(",", "[", "]");
        warnings.forEach(warning -> warningsJson.add(string(warning)));
        return "{\"name\":" + string(name) + ",\"warnings\":" + warningsJson
                + ",\"ambient\":" + colour(scene.getAmbientLighting()) + ",\"light\":" + lightJson
                + ",\"spheres\":" + spheres + "}";
    }

    /** {@code {"error": message}}: what the page shows instead of a scene. */
    static String error(String message) {
        return "{\"error\":" + string(message) + "}";
    }

    /** {@code {"png": base64}}: a ray-traced image, as the page shows it. */
    static String image(byte[] png) {
        return "{\"png\":\"" + Base64.getEncoder().encodeToString(png) + "\"}";
    }

    // The loader accepts only finite numbers, and Java prints those in a form JSON accepts
    // (1.0, -2.5E-4, 1.0E9).
    private static String vector(Vector3 v) {
        return "[" + v.x + "," + v.y + "," + v.z + "]";
    }

    private static String colour(Vector3 c) {
        return String.format("\"#%02X%02X%02X\"", channel(c.x), channel(c.y), channel(c.z));
    }

    private static int channel(double value) {
        return (int) Math.round(Math.max(0, Math.min(1, value)) * 255);
    }

    /** A JSON string literal (RFC 8259 section 7): quote, backslash and control characters escaped. */
    static String string(String text) {
        StringBuilder json = new StringBuilder(text.length() + 2).append('"');
        for (char c : text.toCharArray()) {
            switch (c) {
                case '"' -> json.append("\\\"");
                case '\\' -> json.append("\\\\");
                case '\n' -> json.append("\\n");
                default -> {
                    if (c < 0x20 || c == 0x2028 || c == 0x2029) {
                        json.append(String.format("\\u%04x", (int) c));
                    } else {
                        json.append(c);
                    }
                }
            }
        }
        return json.append('"').toString();
    }
}
