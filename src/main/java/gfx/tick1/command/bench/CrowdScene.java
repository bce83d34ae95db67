package gfx.tick1.command.bench;

import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Deterministic scenes of many spheres for the benchmark: a field of spheres receding from the
 * camera, filling the frame at every size, so that the cost of finding the nearest sphere is
 * what grows with the count. The same count always gives the same file.
 */
public final class CrowdScene {

    private CrowdScene() {
    }

    /** The scene file's text for {@code count} spheres. */
    public static String xml(int count) {
        SplittableRandom random = new SplittableRandom(count);
        StringBuilder xml = new StringBuilder(64 * count + 200);
        xml.append("<scene>\n  <ambient-light colour=\"#303030\"/>\n")
                .append("  <point-light x=\"-4\" y=\"8\" z=\"0\" colour=\"#FFFFFF\" intensity=\"900\"/>\n");
        // Spheres fill a frustum slightly wider than the camera's, at depths 4 to 4 + 40; their
        // radii shrink as their number grows, so that the frame's coverage stays comparable.
        double radius = 1.5 / Math.cbrt(count);
        for (int i = 0; i < count; i++) {
            double z = 4 + 40 * random.nextDouble();
            double x = (random.nextDouble() - 0.5) * 0.9 * z;
            double y = (random.nextDouble() - 0.5) * 0.7 * z;
            double r = radius * (0.5 + random.nextDouble()) * (1 + z / 10);
            xml.append(String.format(Locale.ROOT,
                    "  <sphere x=\"%.4f\" y=\"%.4f\" z=\"%.4f\" radius=\"%.4f\" colour=\"#%06X\"/>%n",
                    x, y, z, r, random.nextInt(1 << 24)));
        }
        return xml.append("</scene>\n").toString();
    }
}
