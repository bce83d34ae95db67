package gfx.tick1.command.shared.diagnosis;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.diagnosis.Diagnosis.Candidate;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.RgbPixels;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Scene;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Says which entry of the catalogue an image is closest to: renders the scene as every
 * {@link Variant} at the image's size and ranks them by how many of the pixels where some entry
 * draws a sphere ({@link SpherePixels}) match.
 */
public final class Diagnoser {

    /**
     * Most exactly equal sphere pixels first; then most sphere pixels within one level (a student's arithmetic
     * in another order moves a few pixels by one level); then the smallest mean difference. On a
     * full tie the correct image wins, so a correct image is never called a mistake merely because
     * the scene does not show that mistake.
     */
    public static final Comparator<Candidate> CLOSEST_FIRST = Comparator
            .comparingDouble(Candidate::exactShare).reversed()
            .thenComparing(Comparator.comparingDouble(Candidate::withinOneShare).reversed())
            .thenComparingDouble(c -> c.difference().meanDifference())
            .thenComparing(c -> !c.variant().isCorrect())
            .thenComparing(Candidate::variant);

    private final int border;
    private final int tolerance;

    /**
     * @param border    the width in pixels of a frame around the image to leave out of every comparison
     * @param tolerance 0: an entry explains the image only when every pixel is equal (as the course's
     *                  tester demands); 1: a mistake also when every pixel is within one level and no
     *                  other entry comes as close (arithmetic written in another order moves a few
     *                  pixels by one level). The correct entry explains it only when every pixel is
     *                  equal, whatever the tolerance.
     */
    public Diagnoser(int border, int tolerance) {
        if (border < 0) {
            throw new IllegalArgumentException("border " + border + ": must be at least 0");
        }
        this.border = border;
        this.tolerance = tolerance;
    }

    /** Exact matches only, no border: as {@code grade} asks. */
    public Diagnoser() {
        this(0, 0);
    }

    /** The scene the handout's figures show, to tell whether an entry may be named with its figure. */
    private static final Scene FIGURES_SCENE = BundledScenes.load(BundledScenes.TICK1);

    /** A diagnosis of the image as a render of one of several scenes: which one, and the diagnosis. */
    public record SceneDiagnosis(String scene, Diagnosis diagnosis) {
    }

    /**
     * The share of pixels whose being background must agree with some entry's render for an image
     * to count as showing a scene: any shading, right or wrong, leaves the spheres' outlines where
     * they are, while another scene's spheres cover other pixels.
     */
    private static final double SAME_SCENE = 0.98;

    /**
     * The entries whose outlines differ from the correct one's: between them they give every
     * outline any entry can give, so that recognising a scene need not render the whole catalogue.
     */
    private static final Set<Variant> OUTLINES = EnumSet.of(Variant.CORRECT, Variant.BACKGROUND_ONLY,
            Variant.UPSIDE_DOWN, Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT);

    /**
     * Which of {@code scenes} (by name) the image shows, and its diagnosis as that scene's: the
     * scene with the best-matching outline (the first named on a tie), or empty when no scene's
     * outline matches at least {@link #SAME_SCENE} of the pixels.
     */
    public Optional<SceneDiagnosis> recognise(BufferedImage image, Map<String, Scene> scenes) {
        checkBorder(image);
        BufferedImage inside = inner(image);
        VariantRenderer renderer = new VariantRenderer(image.getWidth(), image.getHeight());
        String best = null;
        double bestMatch = -1;
        for (Map.Entry<String, Scene> scene : scenes.entrySet()) {
            double match = renderer.render(scene.getValue(), OUTLINES).values().stream()
                    .mapToDouble(render -> outlineMatch(inner(render), inside)).max().orElseThrow();
            if (match > bestMatch) {
                best = scene.getKey();
                bestMatch = match;
            }
        }
        return best == null || bestMatch < SAME_SCENE ? Optional.empty()
                : Optional.of(new SceneDiagnosis(best, diagnose(image, scenes.get(best), best)));
    }

    /**
     * Ranks every catalogue entry against {@code image}, which is taken to show {@code scene}, on
     * the pixels where some entry draws a sphere.
     */
    public Diagnosis diagnose(BufferedImage image, Scene scene) {
        return diagnose(image, scene, null);
    }

    /** As {@link #diagnose(BufferedImage, Scene)}, the report naming the scene {@code name} (null: unnamed). */
    public Diagnosis diagnose(BufferedImage image, Scene scene, String name) {
        return diagnose(image, scene, name, Variant.seenInImages());
    }

    /**
     * As {@link #diagnose(BufferedImage, Scene, String)}, ranking only the entries {@code considered}
     * (the correct one among them): those the code's own answers have not ruled out, so that an
     * entry the code cannot be is neither rendered nor a candidate.
     */
    public Diagnosis diagnose(BufferedImage image, Scene scene, String name, Set<Variant> considered) {
        checkBorder(image);
        int width = image.getWidth(), height = image.getHeight();
        VariantRenderer renderer = new VariantRenderer(width, height);
        // The image, and each render, read once: every entry is compared with the same pixels twice.
        int innerWidth = width - 2 * border, innerHeight = height - 2 * border;
        int[] inside = RgbPixels.of(inner(image));
        Set<Variant> seen = EnumSet.copyOf(considered);
        seen.retainAll(Variant.seenInImages());
        seen.add(Variant.CORRECT);
        VariantRenderer.Renders renders = renderer.renders(scene, seen);
        SpherePixels spheres = SpherePixels.inside(renders.spheres(), width, height, border);
        int[] correct = RgbPixels.of(inner(renders.images().get(Variant.CORRECT)));
        List<Candidate> candidates = new ArrayList<>();
        List<Variant> alikeCorrect = new ArrayList<>();
        renders.images().forEach((variant, render) -> {
            int[] rendered = RgbPixels.of(inner(render));
            // A mistake that draws this scene exactly as the correct code does cannot be seen in it.
            if (!variant.isCorrect() && Arrays.equals(correct, rendered)) {
                alikeCorrect.add(variant);
            } else {
                candidates.add(new Candidate(variant,
                        ImageDifference.between(innerWidth, innerHeight, rendered, inside),
                        spheres.match(rendered, inside)));
            }
        });
        candidates.sort(CLOSEST_FIRST);
        int background = ReferenceRenderer.BACKGROUND_COLOUR.toRGB() & 0xFFFFFF;
        return new Diagnosis(candidates, tolerance, alikeCorrect, spheres.count(),
                spheres.notBackgroundOutside(inside, background), name, SceneChange.same(scene, FIGURES_SCENE));
    }

    /**
     * The scenes one slip away from {@code scene} ({@link SceneChange}, with the values of
     * {@code example} among the slips) whose correct render is the image, pixel for pixel.
     */
    public List<SceneChange> sceneChangesExplaining(BufferedImage image, Scene scene, Scene example) {
        checkBorder(image);
        BufferedImage inside = inner(image);
        VariantRenderer renderer = new VariantRenderer(image.getWidth(), image.getHeight());
        PixelSampler sampler = new PixelSampler(image.getWidth(), image.getHeight());
        return SceneChange.around(scene, example).stream()
                .filter(change -> sampler.mayBe(image, change.scene(), border))
                .filter(change -> samePixels(inner(renderer.render(change.scene(), Variant.CORRECT)), inside))
                .toList();
    }

    /** Whether the image is background on exactly the pixels where the correct render of {@code scene} is. */
    public boolean hasTheOutlineOf(BufferedImage image, Scene scene) {
        checkBorder(image);
        BufferedImage correct = new VariantRenderer(image.getWidth(), image.getHeight()).render(scene, Variant.CORRECT);
        return outlineMatch(inner(correct), inner(image)) == 1;
    }

    private static boolean samePixels(BufferedImage a, BufferedImage b) {
        int width = a.getWidth(), height = a.getHeight();
        return Arrays.equals(a.getRGB(0, 0, width, height, null, 0, width),
                b.getRGB(0, 0, width, height, null, 0, width));
    }

    private void checkBorder(BufferedImage image) {
        int width = image.getWidth(), height = image.getHeight();
        if (width <= 2 * border || height <= 2 * border) {
            throw new IllegalArgumentException("a " + border + "-pixel border leaves nothing of a " + width + " x "
                    + height + " image to compare");
        }
    }

    /** The share of pixels that are background in both images or in neither. */
    private static double outlineMatch(BufferedImage render, BufferedImage image) {
        int background = ReferenceRenderer.BACKGROUND_COLOUR.toRGB() & 0xFFFFFF;
        int width = image.getWidth(), height = image.getHeight();
        int[] a = render.getRGB(0, 0, width, height, null, 0, width);
        int[] b = image.getRGB(0, 0, width, height, null, 0, width);
        long agree = 0;
        for (int i = 0; i < a.length; i++) {
            if (((a[i] & 0xFFFFFF) == background) == ((b[i] & 0xFFFFFF) == background)) {
                agree++;
            }
        }
        return (double) agree / a.length;
    }

    private BufferedImage inner(BufferedImage image) {
        return border == 0 ? image
                : image.getSubimage(border, border, image.getWidth() - 2 * border, image.getHeight() - 2 * border);
    }
}
