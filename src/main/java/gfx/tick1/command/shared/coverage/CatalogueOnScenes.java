package gfx.tick1.command.shared.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.diagnosis.ModelRenderer;
import gfx.tick1.command.shared.diagnosis.VariantRenderer;
import gfx.tick1.engine.image.RgbPixels;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.Scene;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

/**
 * Measures a {@link Coverage}: renders each scene as every catalogued mistake (and as the pairs
 * that need it) at the grading size and counts the pixels that differ from the image a pass needs.
 * {@code grade} passes an image equal to either reference, the handout's arithmetic or tick1's
 * robust one, so a mistake's count is the fewer of its differences from the two.
 */
public final class CatalogueOnScenes {

    private CatalogueOnScenes() {
    }

    /** The catalogue's mistakes: every entry but the correct answers. */
    public static List<Variant> mistakes() {
        return Stream.of(Variant.values()).filter(variant -> !variant.isCorrect()).toList();
    }

    /** The coverage of {@code scenes} in images of {@code width} x {@code height}. */
    public static Coverage measure(List<NamedScene> scenes, int width, int height) {
        List<Variant> mistakes = mistakes();
        List<Counted> counted = scenes.stream().map(scene -> count(scene.scene(), width, height)).toList();
        List<Caught> alone = rows(mistakes.stream().map(List::of).toList(),
                counted.stream().map(Counted::differing).toList());
        Map<Variant, KnownReason> reasons = new EnumMap<>(Variant.class);
        List<Scene> plain = scenes.stream().map(NamedScene::scene).toList();
        alone.stream().filter(row -> !row.caught()).forEach(row -> KnownReason.of(row.entries().get(0), plain)
                .ifPresent(reason -> reasons.put(row.entries().get(0), reason)));
        Caught sixSteps = new Caught(List.of(Variant.HANDOUT_SIX_STEPS),
                counted.stream().map(Counted::sixSteps).toList());
        return new Coverage(scenes.stream().map(NamedScene::name).toList(), width, height, alone,
                pairs(scenes, counted.stream().map(Counted::references).toList(), alone, width, height), reasons,
                sixSteps);
    }

    /** The mistakes at least one of {@code scenes} catches in images of {@code width} x {@code height}. */
    public static Set<Variant> caught(List<Scene> scenes, int width, int height) {
        Set<Variant> caught = EnumSet.noneOf(Variant.class);
        scenes.forEach(scene -> caught.addAll(count(scene, width, height).caught()));
        return caught;
    }

    /**
     * One scene judged as a grading scene: the mistakes it catches, whether the handout's six steps
     * taken literally (a correct answer) pass it, and whether its two references are the same image.
     */
    public record Judged(Set<Variant> caught, boolean passesTheSixSteps, boolean referencesAgree) {
    }

    /** {@code scene} judged in images of {@code width} x {@code height}. */
    public static Judged judge(Scene scene, int width, int height) {
        Counted counted = count(scene, width, height);
        return new Judged(counted.caught(), counted.sixSteps() == 0,
                References.count(counted.references().handout(), counted.references().robust()) == 0);
    }

    /**
     * Each mistake's pixels differing on one scene, in the order of {@link #mistakes()}, those of
     * the handout's six steps taken literally, and the scene's references.
     */
    private record Counted(long[] differing, long sixSteps, References references) {
        Set<Variant> caught() {
            List<Variant> mistakes = mistakes();
            Set<Variant> caught = EnumSet.noneOf(Variant.class);
            for (int i = 0; i < mistakes.size(); i++) {
                if (differing[i] > 0) {
                    caught.add(mistakes.get(i));
                }
            }
            return caught;
        }
    }

    private static Counted count(Scene scene, int width, int height) {
        List<Variant> mistakes = mistakes();
        Set<Variant> rendered = EnumSet.copyOf(mistakes);
        rendered.add(Variant.CORRECT);
        rendered.add(Variant.HANDOUT_SIX_STEPS);
        Map<Variant, BufferedImage> images = new VariantRenderer(width, height).render(scene, rendered);
        References pass = new References(RgbPixels.of(images.get(Variant.CORRECT)),
                RgbPixels.of(new ReferenceRenderer(width, height, Intersection.ROBUST).render(scene)));
        long[] differing = new long[mistakes.size()];
        for (int i = 0; i < mistakes.size(); i++) {
            differing[i] = pass.differing(RgbPixels.of(images.get(mistakes.get(i))));
        }
        return new Counted(differing, pass.differing(RgbPixels.of(images.get(Variant.HANDOUT_SIX_STEPS))), pass);
    }

    /**
     * The pairs {@code grade} can name (two entries of intersectionWith, or two of illuminate) that
     * some scene catches neither of alone, each measured on every scene.
     */
    private static List<Caught> pairs(List<NamedScene> scenes, List<References> references, List<Caught> alone,
            int width, int height) {
        List<List<Variant>> pairs = new ArrayList<>();
        for (int i = 0; i < alone.size(); i++) {
            for (int j = i + 1; j < alone.size(); j++) {
                Caught a = alone.get(i), b = alone.get(j);
                Variant.Method method = a.entries().get(0).method();
                boolean nameable = method == b.entries().get(0).method() && method != Variant.Method.RENDER;
                boolean someSceneCatchesNeither = false;
                for (int s = 0; s < scenes.size(); s++) {
                    someSceneCatchesNeither |= !a.caughtBy(s) && !b.caughtBy(s);
                }
                if (nameable && someSceneCatchesNeither) {
                    pairs.add(List.of(a.entries().get(0), b.entries().get(0)));
                }
            }
        }
        if (pairs.isEmpty()) {
            return List.of();
        }
        List<Set<Variant>> models = pairs.stream().map(EnumSet::copyOf).map(set -> (Set<Variant>) set).toList();
        List<long[]> counts = new ArrayList<>();
        for (int s = 0; s < scenes.size(); s++) {
            List<int[]> images = new ModelRenderer(width, height).render(scenes.get(s).scene(), models);
            long[] differing = new long[pairs.size()];
            for (int p = 0; p < pairs.size(); p++) {
                differing[p] = references.get(s).differing(images.get(p));
            }
            counts.add(differing);
        }
        return rows(pairs, counts);
    }

    /** A row for each of {@code entries}, with its count from each scene's {@code counts}, in the same order. */
    private static List<Caught> rows(List<List<Variant>> entries, List<long[]> counts) {
        List<Caught> rows = new ArrayList<>();
        for (int i = 0; i < entries.size(); i++) {
            List<Long> pixels = new ArrayList<>();
            for (long[] sceneCounts : counts) {
                pixels.add(sceneCounts[i]);
            }
            rows.add(new Caught(entries.get(i), pixels));
        }
        return rows;
    }

    /** The two images a pass may equal, as 0xRRGGBB pixels. */
    private record References(int[] handout, int[] robust) {
        long differing(int[] image) {
            return Math.min(count(handout, image), count(robust, image));
        }

        static long count(int[] expected, int[] image) {
            long differing = 0;
            for (int i = 0; i < image.length; i++) {
                if ((expected[i] & 0xFFFFFF) != (image[i] & 0xFFFFFF)) {
                    differing++;
                }
            }
            return differing;
        }
    }
}
