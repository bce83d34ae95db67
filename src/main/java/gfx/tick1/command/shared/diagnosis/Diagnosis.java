package gfx.tick1.command.shared.diagnosis;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.io.Counted;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * Every catalogue entry's distance from an image, closest first, and what can be said for
 * certain: an entry explains the image only when its render matches every pixel of the frame
 * (exactly, or, for a mistake, within the 1-level tolerance when that is allowed); the image is
 * correct only when every pixel is the correct render's, and one within a level of it everywhere
 * is said to be so; anything less is reported as at most three candidates, and no entry is then
 * called the closest.
 *
 * @param candidates   one per {@link Variant} seen in images, ordered as {@link Diagnoser#CLOSEST_FIRST}
 * @param tolerance    0, or 1 to let a mistake within one level on every pixel explain the image
 * @param alikeCorrect the mistakes left out of the ranking because on this scene they draw exactly
 *                     the correct image (a hit rejected when a root is negative, with the camera
 *                     outside every sphere), so that no image can tell them apart from it
 * @param spherePixels how many pixels the ranking counts: those where some entry draws a sphere
 * @param strayPixels  how many of the other pixels, background in every entry, are not background
 *                     in the image
 * @param scene        the scene the image was compared with, as the report names it ("tick1.xml")
 * @param figures      whether the handout's figures show this scene (they all show tick1.xml), so
 *                     that an entry may be named with its figure
 */
public record Diagnosis(List<Candidate> candidates, int tolerance, List<Variant> alikeCorrect, int spherePixels,
        int strayPixels, String scene, boolean figures) {

    /** Candidates shown when no entry explains the image. */
    private static final int MOST_CANDIDATES = 3;

    /**
     * Two entries whose shares of exactly matching pixels are closer than this (0.1 percentage
     * points) are a near tie: the image does not tell them apart, so neither is called the winner.
     */
    private static final double NEAR_TIE = 0.001;

    /**
     * One catalogue entry, how the image differs from its render over the whole frame, and how
     * they agree on the sphere pixels, which rank it.
     */
    public record Candidate(Variant variant, ImageDifference difference, SpherePixels.Match onSpheres) {

        /** The share (0 to 1) of sphere pixels equal to this entry's render. */
        public double exactShare() {
            return onSpheres.exactShare();
        }

        /** The share (0 to 1) of sphere pixels within one level of this entry's render in every channel. */
        public double withinOneShare() {
            return onSpheres.withinOneShare();
        }

        boolean matchesExactly() {
            return difference.differingPixels() == 0;
        }

        boolean matchesWithinOneLevel() {
            return difference.isWithin(1);
        }
    }

    /** What the image is, as far as the catalogue can tell. */
    public enum Verdict {
        /** The correct render: every pixel equal. */
        CORRECT,
        /**
         * Not the correct render, but within one level of it on every pixel: the same formulas in
         * float, or in another order, round so. {@code grade} fails such an image.
         */
        LEVEL_OFF_CORRECT,
        /** One stage or mistake (or several that look the same on this scene) explains every pixel. */
        EXPLAINED,
        /** No entry explains the image, or two come out level: only candidates can be shown. */
        UNSURE
    }

    public Diagnosis {
        candidates = List.copyOf(candidates);
        alikeCorrect = List.copyOf(alikeCorrect);
        if (tolerance < 0 || tolerance > 1) {
            throw new IllegalArgumentException("tolerance " + tolerance + ": must be 0 or 1");
        }
    }

    public Candidate closest() {
        return candidates.get(0);
    }

    public List<Candidate> top(int count) {
        return candidates.subList(0, Math.min(count, candidates.size()));
    }

    /**
     * The entries that explain every pixel: those matching exactly; failing that, with a
     * tolerance of 1, the closest mistake within one level everywhere, unless another such entry is
     * a near tie with it, and unless the correct render is within one level too (then the image is
     * {@link Verdict#LEVEL_OFF_CORRECT}, and no mistake is named). When the correct render matches
     * exactly, it alone: a mistake that looks the same as the correct image on this scene does no
     * harm here.
     */
    public List<Candidate> explaining() {
        List<Candidate> exact = candidates.stream().filter(Candidate::matchesExactly).toList();
        if (exact.isEmpty() && tolerance == 1 && levelOffCorrect() == null) {
            List<Candidate> within = candidates.stream().filter(Candidate::matchesWithinOneLevel).toList();
            exact = within.isEmpty() ? within : tiedWith(within.get(0), within);
        }
        return exact.stream().anyMatch(c -> c.variant().isCorrect())
                ? exact.stream().filter(c -> c.variant().isCorrect()).toList() : exact;
    }

    /** The correct entry when it is within one level of the image on every pixel but not equal on all; else null. */
    private Candidate levelOffCorrect() {
        return candidates.stream().filter(c -> c.variant().isCorrect() && !c.matchesExactly()
                && c.matchesWithinOneLevel()).findFirst().orElse(null);
    }

    public Verdict verdict() {
        List<Candidate> explaining = explaining();
        if (explaining.isEmpty()) {
            return levelOffCorrect() != null ? Verdict.LEVEL_OFF_CORRECT : Verdict.UNSURE;
        }
        if (explaining.get(0).variant().isCorrect()) {
            return Verdict.CORRECT;
        }
        // Several entries each matching every pixel exactly are one explanation as far as the image
        // goes (the scene cannot tell them apart); within the tolerance, a tie means no winner.
        return explaining.size() == 1 || explaining.get(0).matchesExactly() ? Verdict.EXPLAINED : Verdict.UNSURE;
    }

    /**
     * Whether even the closest entry leaves most pixels more than a level off: then the image
     * probably shows another scene, another size of image, or a mistake not in the catalogue.
     */
    private boolean isWeak() {
        return closest().withinOneShare() < 0.5;
    }

    /**
     * The diagnosis for a person. When an entry explains the image: the closest entry, the top
     * three, the verdict, why, and what to reread. Otherwise: that it is unsure, and at most three
     * candidates with what to reread for each; no entry is called the closest.
     */
    public List<String> report() {
        return report(true);
    }

    /**
     * What the report's "reread:" line names, when it has one ("handout section 5 ..."): the section of
     * the one entry that explains the image, or the arithmetic of an image one level off the correct one.
     */
    public Optional<String> toReread() {
        return switch (verdict()) {
            case LEVEL_OFF_CORRECT -> Optional.of(
                    "handout section 5 (compute each term in double, in the order the handout writes it).");
            case EXPLAINED -> explaining().size() == 1
                    ? Optional.of(explaining().get(0).variant().rereadWhere() + ".") : Optional.empty();
            default -> Optional.empty();
        };
    }

    /**
     * The diagnosis for a person, as {@link #report()} gives it, with its "reread:" line only when
     * {@code reread}: a grade leaves it out where the tested findings, not the image, say what to reread.
     */
    public List<String> report(boolean reread) {
        return report(reread, Set.of());
    }

    /**
     * The diagnosis for a person, as {@link #report(boolean)} gives it, with no entry of
     * {@code ruledOut} given as a cause or a candidate: the code that drew the image answers
     * otherwise than their models.
     */
    public List<String> report(boolean reread, Set<Variant> ruledOut) {
        return report(reread, ruledOut, false);
    }

    /**
     * The diagnosis for a person, as {@link #report(boolean, Set)} gives it; with {@code rendered}, the image
     * is one tick1 had the code render from this scene itself, so it is never said to show another scene.
     */
    public List<String> report(boolean reread, Set<Variant> ruledOut, boolean rendered) {
        List<String> lines = new ArrayList<>();
        Verdict verdict = verdict();
        // An image one level off the correct render has no entry to call the closest: the correct image, which
        // it is not, is nearest; and an image that is not the correct render is never ranked beside it.
        if (verdict == Verdict.CORRECT || verdict == Verdict.EXPLAINED) {
            List<Candidate> ranked = verdict == Verdict.CORRECT ? candidates
                    : candidates.stream().filter(c -> !c.variant().isCorrect()).toList();
            lines.add("closest: " + title(ranked.get(0).variant()) + " (" + shares(ranked.get(0)) + ")");
            lines.add("top three:");
            List<Candidate> top = ranked.subList(0, Math.min(3, ranked.size()));
            for (int i = 0; i < top.size(); i++) {
                lines.add(line(ranked, i, top.get(i)));
            }
            lines.add(onWhichPixels());
        }
        List<Candidate> explaining = explaining();
        switch (verdict) {
            case CORRECT -> correct(lines, explaining.get(0));
            case LEVEL_OFF_CORRECT -> levelOff(lines, levelOffCorrect(), reread);
            case EXPLAINED -> explained(lines, explaining, reread, ruledOut);
            case UNSURE -> unsure(lines, ruledOut, rendered);
            default -> throw new IllegalStateException();
        }
        return lines;
    }

    /**
     * An entry as the report names it: with its handout figure only when the figures show this
     * scene, and the correct entry as "the correct image", never as a bare "correct" that could
     * be read as a verdict.
     */
    String title(Variant variant) {
        String title = figures ? variant.title() : variant.title().replaceFirst(" \\((like )?Figure \\w+\\)$", "");
        return variant.isCorrect() ? "the correct image" + title.substring("correct".length()) : title;
    }

    /** "of tick1.xml", or nothing when the scene has no name. */
    private String ofTheScene() {
        return scene == null ? "" : " of " + scene;
    }

    /** The line of {@code candidate}, ranked {@code index} among {@code ranked}. */
    private String line(List<Candidate> ranked, int index, Candidate candidate) {
        return String.format("  %s %-45s %s", rank(ranked, index), title(candidate.variant()), shares(candidate));
    }

    private String onWhichPixels() {
        return "  (shares of the " + Counted.of(spherePixels, "pixel") + " where some entry draws a sphere; "
                + "elsewhere every entry draws the background)";
    }

    private void correct(List<String> lines, Candidate correct) {
        lines.add("verdict: correct: every pixel is the correct render's" + ofTheScene() + ".");
        lines.add("this is " + correct.variant().explanation() + (figures ? " (Figure 1)." : "."));
        if (!alikeCorrect.isEmpty()) {
            lines.add("(on this scene these mistakes would draw the same image, so they are not ruled out: "
                    + String.join(", ", alikeCorrect.stream().map(this::title).toList()) + ")");
        }
    }

    /** Every pixel within one level of the correct render, some not equal: not correct, and why it may be so. */
    private void levelOff(List<String> lines, Candidate correct, boolean reread) {
        ImageDifference difference = correct.difference();
        int off = difference.differingPixels();
        lines.add("verdict: not correct: " + Counted.of(off, "pixel") + " of " + difference.totalPixels()
                + (off == 1 ? " differs" : " differ") + " from the correct render" + ofTheScene()
                + ", by 1 level in a channel; the tester, and tick1 grade, want every pixel equal.");
        lines.add("possible cause: the same formulas computed in float rather than double, or in another order "
                + "than the handout's, round some colours to the next level.");
        if (reread) {
            lines.add("reread: " + toReread().orElseThrow());
        }
    }

    private void explained(List<String> lines, List<Candidate> explaining, boolean reread, Set<Variant> ruledOut) {
        if (explaining.size() == 1) {
            Candidate only = explaining.get(0);
            int off = only.difference().differingPixels();
            lines.add("verdict: " + title(only.variant()) + (only.matchesExactly()
                    ? ": every pixel matches its render" + ofTheScene() + " exactly."
                    : ": every pixel within 1 level of its render" + ofTheScene() + " (" + Counted.of(off, "pixel")
                            + " 1 level off, as the same formulas in float or in another order give)."));
            if (ruledOut.contains(only.variant())) {
                lines.add("not its cause here: your methods' answers are not those of its model, so another slip "
                        + "draws the same image on this scene.");
                return;
            }
            lines.add("likely cause: " + only.variant().explanation() + ".");
            if (reread) {
                lines.add("reread: " + toReread().orElseThrow());
            }
            return;
        }
        lines.add("verdict: a tie: " + titles(explaining) + " each match every pixel exactly; this "
                + "scene cannot tell them apart.");
        for (Candidate candidate : explaining.stream().filter(c -> !ruledOut.contains(c.variant())).toList()) {
            lines.add("if it is " + title(candidate.variant()) + ": " + candidate.variant().explanation()
                    + "; reread " + candidate.variant().rereadWhere() + ".");
        }
    }

    /**
     * No entry explains the image: say so, and show the closest few as candidates, never as the
     * answer; never the correct image, which the image is not, nor an entry of {@code ruledOut}.
     */
    private void unsure(List<String> lines, Set<Variant> ruledOut, boolean rendered) {
        Candidate best = closest();
        List<Candidate> possible = candidates.stream().filter(c -> !c.variant().isCorrect()
                && !ruledOut.contains(c.variant())).toList();
        // An entry that gets no pixel right is no lead.
        List<Candidate> pool = possible.stream().filter(c -> c.exactShare() > 0).toList();
        lines.add("verdict: unsure: no entry of the catalogue explains this image exactly; it is not the correct "
                + "image, and it may show a mistake the catalogue does not know, or two at once.");
        if (isWeak() && !rendered) {
            lines.add("  (a weak match: the image may show another scene or a mistake not in the catalogue)");
        }
        if (best.variant().isCorrect()) {
            int off = best.difference().differingPixels();
            lines.add("the nearest render is the correct one, but " + Counted.of(off, "pixel") + (off == 1
                    ? " differs" : " differ") + " from it, by up to " + Counted.of(best.difference().maxDifference(),
                    "level") + ".");
        }
        List<Candidate> level = pool.isEmpty() ? pool : tiedWith(pool.get(0), pool);
        List<Candidate> shown = (level.size() > 1 ? level : pool).subList(0,
                Math.min(MOST_CANDIDATES, level.size() > 1 ? level.size() : pool.size()));
        lines.add(pool.isEmpty() ? possible.isEmpty()
                ? "candidates: none; your methods' answers rule out every entry that draws a sphere"
                : "candidates: none; no entry your methods' answers leave possible gets a sphere pixel right"
                : level.size() > 1
                ? "candidates, in a near tie (within " + percent(NEAR_TIE) + " of the sphere pixels):"
                : "candidates, closest first:");
        for (int i = 0; i < shown.size(); i++) {
            lines.add(line(pool, i, shown.get(i)));
        }
        if (level.size() > shown.size()) {
            lines.add("  (and " + (level.size() - shown.size()) + " more level with them)");
        }
        lines.add(onWhichPixels());
        if (strayPixels > 0) {
            lines.add(Counted.of(strayPixels, "pixel") + " where no entry draws a sphere "
                    + (strayPixels == 1 ? "is" : "are") + " not the background.");
        }
        for (Candidate candidate : shown) {
            if (!candidate.variant().isCorrect()) {
                lines.add("if it is " + title(candidate.variant()) + ": reread " + candidate.variant().rereadWhere()
                        + ".");
            }
        }
    }

    /** "1.", or "1=" for the members of a near tie, ranked by the first of them. */
    private static String rank(List<Candidate> candidates, int index) {
        int first = index;
        while (first > 0 && nearTie(candidates.get(first - 1), candidates.get(index))) {
            first--;
        }
        boolean tied = first < index
                || (index + 1 < candidates.size() && nearTie(candidates.get(index), candidates.get(index + 1)));
        return (first + 1) + (tied ? "=" : ".");
    }

    /** {@code leader} and the entries of {@code among} in a near tie with it. */
    private static List<Candidate> tiedWith(Candidate leader, List<Candidate> among) {
        return among.stream().filter(c -> c == leader || nearTie(leader, c)).toList();
    }

    private static boolean nearTie(Candidate a, Candidate b) {
        return Math.abs(a.exactShare() - b.exactShare()) < NEAR_TIE;
    }

    private String titles(List<Candidate> candidates) {
        return String.join(", ", candidates.stream().map(c -> title(c.variant())).toList());
    }

    private static String percent(double share) {
        return String.format("%.1f%%", 100 * share);
    }

    private static String shares(Candidate candidate) {
        return String.format("%7.3f%% of pixels exact, %7.3f%% within 1 level", 100 * candidate.exactShare(),
                100 * candidate.withinOneShare());
    }
}
