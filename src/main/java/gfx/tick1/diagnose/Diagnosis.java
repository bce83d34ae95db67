package gfx.tick1.diagnose;

import gfx.tick1.image.ImageDifference;
import java.util.ArrayList;
import java.util.List;

/**
 * Every catalogue entry's distance from an image, closest first.
 *
 * @param candidates one per {@link Variant}, ordered as {@link Diagnoser#CLOSEST_FIRST} orders them
 */
public record Diagnosis(List<Candidate> candidates) {

    /** One catalogue entry and how the image differs from its render. */
    public record Candidate(Variant variant, ImageDifference difference) {

        /** The share (0 to 1) of pixels equal to this entry's render. */
        public double exactShare() {
            return difference.shareWithin(0);
        }

        /** The share (0 to 1) of pixels within one level of this entry's render in every channel. */
        public double withinOneShare() {
            return difference.shareWithin(1);
        }
    }

    public Diagnosis {
        candidates = List.copyOf(candidates);
    }

    public Candidate closest() {
        return candidates.get(0);
    }

    public List<Candidate> top(int count) {
        return candidates.subList(0, Math.min(count, candidates.size()));
    }

    /**
     * Whether even the closest entry leaves most pixels more than a level off: then the image
     * probably shows another scene, another size of image, or a mistake not in the catalogue.
     */
    public boolean isWeak() {
        return closest().withinOneShare() < 0.5;
    }

    /** The diagnosis for a person: the closest entry, the top three, why, and what to reread. */
    public List<String> report() {
        List<String> lines = new ArrayList<>();
        Candidate best = closest();
        lines.add("closest: " + best.variant().title() + " (" + shares(best) + ")");
        if (isWeak()) {
            lines.add("  (a weak match: the image may show another scene or a mistake not in the catalogue)");
        }
        lines.add("top three:");
        int rank = 1;
        for (Candidate candidate : top(3)) {
            lines.add(String.format("  %d. %-45s %s", rank++, candidate.variant().title(), shares(candidate)));
        }
        Variant variant = best.variant();
        lines.add((variant.isCorrect() ? "this is " : "likely cause: ") + variant.explanation() + ".");
        if (!variant.isCorrect()) {
            lines.add("reread: handout " + variant.reread() + ".");
        }
        return lines;
    }

    private static String shares(Candidate candidate) {
        return String.format("%7.3f%% of pixels exact, %7.3f%% within 1 level", 100 * candidate.exactShare(),
                100 * candidate.withinOneShare());
    }
}
