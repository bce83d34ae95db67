package gfx.tick1.diagnose;

import gfx.tick1.diagnose.Diagnosis.Candidate;
import gfx.tick1.image.ImageDifference;
import gfx.tick1.scene.Scene;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumSet;
import java.util.List;

/**
 * Says which entry of the catalogue an image is closest to: renders the scene as every
 * {@link Variant} at the image's size and ranks them by how many pixels match.
 */
public final class Diagnoser {

    /**
     * Most exactly equal pixels first; then most pixels within one level (a student's arithmetic
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

    /** @param border the width in pixels of a frame around the image to leave out of every comparison */
    public Diagnoser(int border) {
        if (border < 0) {
            throw new IllegalArgumentException("border " + border + ": must be at least 0");
        }
        this.border = border;
    }

    public Diagnoser() {
        this(0);
    }

    /** Ranks every catalogue entry against {@code image}, which is taken to show {@code scene}. */
    public Diagnosis diagnose(BufferedImage image, Scene scene) {
        int width = image.getWidth(), height = image.getHeight();
        if (width <= 2 * border || height <= 2 * border) {
            throw new IllegalArgumentException("a " + border + "-pixel border leaves nothing of a " + width + " x "
                    + height + " image to compare");
        }
        VariantRenderer renderer = new VariantRenderer(width, height);
        BufferedImage inside = inner(image);
        List<Candidate> candidates = new ArrayList<>();
        renderer.render(scene, EnumSet.allOf(Variant.class)).forEach((variant, render) ->
                candidates.add(new Candidate(variant, ImageDifference.between(inner(render), inside))));
        candidates.sort(CLOSEST_FIRST);
        return new Diagnosis(candidates);
    }

    private BufferedImage inner(BufferedImage image) {
        return border == 0 ? image
                : image.getSubimage(border, border, image.getWidth() - 2 * border, image.getHeight() - 2 * border);
    }
}
