package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.behaviour.Answers.Colour;
import gfx.tick1.command.shared.behaviour.Answers.Hit;
import gfx.tick1.command.shared.behaviour.BehaviourJudge.RayCase;
import gfx.tick1.command.shared.behaviour.BehaviourJudge.ShadeCase;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * Properties checked on the student's answers alone, whatever the mistake: a hit's normal is a
 * unit vector, its distance is positive, its point is O + s D; a colour has no NaN and no negative
 * channel. Each fact names the simplest input that shows it.
 */
final class AnswerFacts {

    private static final double UNIT = 1e-6;

    private AnswerFacts() {
    }

    static List<String> ofHits(List<RayCase> cases) {
        List<String> facts = new ArrayList<>();
        simplest(cases, c -> hit(c) != null && Math.abs(BehaviourJudge.length(hit(c).normal()) - 1) > UNIT)
                .ifPresent(c -> {
                    double length = BehaviourJudge.length(hit(c).normal());
                    boolean radius = cases.stream().filter(d -> hit(d) != null)
                            .allMatch(d -> Math.abs(BehaviourJudge.length(hit(d).normal()) - d.call().radius()) <= UNIT
                                    * Math.max(1, d.call().radius()));
                    facts.add("the normal you return has length " + Words.number(length) + ", not 1"
                            + (radius ? " (always the sphere's radius r)" : "") + ", for " + Words.ray(c.call()));
                });
        simplest(cases, c -> hit(c) != null && hit(c).distance() < 0).ifPresent(c -> facts.add(
                "the distance you return is negative (s = " + Words.number(hit(c).distance()) + ") for "
                        + Words.ray(c.call())));
        simplest(cases, c -> hit(c) != null && !onTheRay(c)).ifPresent(c -> facts.add(
                "the point you return is not O + s D for the distance s you return, for " + Words.ray(c.call())));
        return facts;
    }

    static List<String> ofColours(List<ShadeCase> cases) {
        List<String> facts = new ArrayList<>();
        simplest(cases, c -> rgb(c) != null && (Double.isNaN(rgb(c)[0]) || Double.isNaN(rgb(c)[1])
                || Double.isNaN(rgb(c)[2]))).ifPresent(c -> facts.add("the colour you return is NaN for "
                        + Words.shading(c.call(), c.phong())));
        simplest(cases, c -> rgb(c) != null && (rgb(c)[0] < 0 || rgb(c)[1] < 0 || rgb(c)[2] < 0)).ifPresent(c ->
                facts.add("the colour you return has a negative channel, " + Words.vector(rgb(c)) + ", for "
                        + Words.shading(c.call(), c.phong())));
        return facts;
    }

    private static Hit hit(RayCase c) {
        return c.answer() instanceof Hit hit && hit.sameSphere() ? hit : null;
    }

    private static double[] rgb(ShadeCase c) {
        return c.answer() instanceof Colour colour ? colour.rgb() : null;
    }

    private static boolean onTheRay(RayCase c) {
        Hit hit = hit(c);
        double[] o = c.call().origin(), d = c.call().direction(), p = hit.point();
        double size = Math.max(1, Math.max(BehaviourJudge.length(o), BehaviourJudge.length(p)));
        for (int i = 0; i < 3; i++) {
            if (!(Math.abs(o[i] + hit.distance() * d[i] - p[i]) <= BehaviourJudge.TOLERANCE * size)) {
                return false;
            }
        }
        return true;
    }

    private static <T> Optional<T> simplest(List<T> cases, Predicate<T> shows) {
        return cases.stream().filter(shows).min(Comparator.comparingDouble(c -> c instanceof RayCase r
                ? Words.roughness(r.call()) : Words.roughness(((ShadeCase) c).call())));
    }
}
