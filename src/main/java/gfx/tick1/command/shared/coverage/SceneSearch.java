package gfx.tick1.command.shared.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneLoader;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.math.BigDecimal;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.Set;

/**
 * Finds a hidden scene, in the tick's format, that catches every catalogued mistake a fair scene
 * can show: one that every answer as correct as ours passes (the handout's six steps taken
 * literally among them), and whose two references are the same image, so that nothing hangs on
 * which one a student's arithmetic follows. Each candidate keeps tick1.xml's ambient light and two
 * spheres, and draws from a {@link Random} of a fixed seed (so the search gives the same scene on
 * every run) a position for the light, a third sphere farther away (where roots kept in float are
 * further off) and the radius of a fourth behind the camera whose surface passes exactly through
 * it (c = 0: correct code finds no hit in front of the camera; a root accepted at s = 0 hits it at
 * the camera on every ray). The first candidate that catches every such mistake is kept.
 */
public final class SceneSearch {

    /** The candidates tried before the best so far is given. */
    static final int CANDIDATES = 20;
    private static final long SEED = 43;

    /**
     * The scene found: its file's text, the scene as tick1 reads that text, which candidate it was
     * (1 for the first), and the mistakes it catches and misses of those a fair scene can show.
     */
    public record Suggestion(String xml, Scene scene, int candidate, Set<Variant> caught, Set<Variant> missed) {
    }

    private SceneSearch() {
    }

    /** The mistakes a fair scene of the tick can show: the catalogue's but those {@link KnownReason} rules out. */
    public static Set<Variant> showable() {
        Set<Variant> showable = EnumSet.copyOf(CatalogueOnScenes.mistakes());
        showable.removeAll(KnownReason.shownByNoFairScene());
        return showable;
    }

    /**
     * Searches at {@code width} x {@code height}: the first fair candidate that catches every
     * showable mistake, else the fair one that misses the fewest (null if none was fair).
     */
    public static Suggestion find(int width, int height) {
        Scene tick1 = BundledScenes.load(BundledScenes.TICK1);
        Random random = new Random(SEED);
        Set<Variant> showable = showable();
        Suggestion best = null;
        for (int candidate = 1; candidate <= CANDIDATES; candidate++) {
            String xml = layout(tick1, new Vector3(round(random, -4, 4), round(random, 0, 5), round(random, -1, 3)),
                    new Vector3(round(random, -3, 3), round(random, -2, 2), round(random, 12, 30)),
                    round(random, 1.5, 4), 1 + random.nextInt(4),
                    new Vector3(random.nextInt(256) / 255.0, random.nextInt(256) / 255.0,
                            random.nextInt(256) / 255.0));
            Scene scene = new SceneLoader("suggested.xml", xml.getBytes(StandardCharsets.UTF_8), true).getScene();
            CatalogueOnScenes.Judged judged = CatalogueOnScenes.judge(scene, width, height);
            if (!judged.passesTheSixSteps() || !judged.referencesAgree()) {
                continue;
            }
            Set<Variant> caught = EnumSet.copyOf(showable);
            caught.retainAll(judged.caught());
            Set<Variant> missed = EnumSet.copyOf(showable);
            missed.removeAll(caught);
            Suggestion suggestion = new Suggestion(xml, scene, candidate, caught, missed);
            if (missed.isEmpty()) {
                return suggestion;
            }
            if (best == null || missed.size() < best.missed().size()) {
                best = suggestion;
            }
        }
        return best;
    }

    /**
     * tick1.xml's ambient light, point light (moved to {@code light}) and spheres, a sphere of
     * {@code farRadius} at {@code far}, and one of radius {@code behind} centred that far behind
     * the camera.
     */
    private static String layout(Scene tick1, Vector3 light, Vector3 far, double farRadius, int behind,
            Vector3 colour) {
        PointLight tickLight = tick1.getPointLight();
        List<String> lines = new ArrayList<>();
        lines.add("<!-- Suggested by tick1 coverage as a hidden scene: tick1.xml's spheres with the light moved, a "
                + "sphere farther");
        lines.add("     away, and one behind the camera whose surface passes through it. -->");
        lines.add("<scene>");
        lines.add("  <ambient-light colour=\"" + hex(tick1.getAmbientLighting()) + "\"/>");
        lines.add("  <point-light " + xyz(light) + " colour=\"" + hex(tickLight.getColour()) + "\" intensity=\""
                + number(tickLight.getIntensity()) + "\"/>");
        for (Sphere sphere : tick1.getObjects()) {
            lines.add(sphere(SphereGeometry.centre(sphere), SphereGeometry.radius(sphere), sphere.getColour()));
        }
        lines.add(sphere(far, farRadius, colour));
        lines.add(sphere(new Vector3(0, 0, -behind), behind, new Vector3(colour.z, colour.x, colour.y)));
        lines.add("</scene>");
        return String.join("\n", lines) + "\n";
    }

    private static String sphere(Vector3 centre, double radius, Vector3 colour) {
        return "  <sphere " + xyz(centre) + " radius=\"" + number(radius) + "\" colour=\"" + hex(colour) + "\"/>";
    }

    private static String xyz(Vector3 p) {
        return "x=\"" + number(p.x) + "\" y=\"" + number(p.y) + "\" z=\"" + number(p.z) + "\"";
    }

    private static String number(double value) {
        return BigDecimal.valueOf(value).stripTrailingZeros().toPlainString();
    }

    private static String hex(Vector3 colour) {
        return String.format(Locale.ROOT, "#%02X%02X%02X", Math.round(colour.x * 255), Math.round(colour.y * 255),
                Math.round(colour.z * 255));
    }

    /** A number from {@code from} to {@code to} to two decimals, as a person would write it. */
    private static double round(Random random, double from, double to) {
        return Math.round((from + random.nextDouble() * (to - from)) * 100) / 100.0;
    }
}
