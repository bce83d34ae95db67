package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.behaviour.Answers.Answer;
import gfx.tick1.command.shared.behaviour.Answers.Colour;
import gfx.tick1.command.shared.behaviour.Answers.Hit;
import gfx.tick1.command.shared.behaviour.Answers.None;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Sphere;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;
import java.util.stream.IntStream;
import java.util.stream.Stream;

/**
 * Compares the student's answers with ours, input by input, and with the catalogue's models of
 * the same methods ({@link Models}). An answer is ours when it agrees with the reference's
 * within {@link #TOLERANCE}: a hit's distance, point and normal relative to the input's size, a
 * colour channel by channel once both are clamped to [0, 1] as toRGB() clamps them (a colour
 * clamped by the student's code is a correct answer). A hit is also ours when it is the exact
 * answer (106-bit arithmetic, {@link Intersection#ROBUST}) where the handout's formula is not.
 * A mistake is named only when its model, alone or with one other, gives every answer the
 * student's method gave on the tested inputs.
 */
final class BehaviourJudge {

    /**
     * The one label of an answer neither tick1.xml nor the hidden scene can show: a note is made only
     * where the answer is neither ours nor the handout's six steps', the two the handout allows, so
     * it is a mistake, though never a reason to fail.
     */
    static final String UNTESTED = "a mistake not tested by the course's scenes";

    /**
     * Relative tolerance: correct code written another way differs from ours in the last bits
     * (docs/grading.md gives the figures); roots kept in float differ in the eighth digit.
     */
    static final double TOLERANCE = 1e-9;

    /** The edge cases the course's scenes cannot show, and what each one is in words. */
    private static final List<String> UNTESTED_EDGES = List.of("graze", "inside", "surface");

    static final Set<Variant> OURS = EnumSet.noneOf(Variant.class);

    private BehaviourJudge() {
    }

    /**
     * Said of a counterexample when no differing answer moves a byte of the image: toRGB() gives
     * the same three bytes for the student's colour and ours on every input where they differ.
     */
    static final String BELOW_ONE_LEVEL = "every difference is smaller than one colour level: toRGB() gives the "
            + "same bytes for yours and ours";

    /** One tested input and the student's answer to it. */
    interface Case {
        /** Whether the answer is that of the model of {@code variants} (none: ours in plain doubles). */
        boolean answerIs(Set<Variant> variants);

        /** Whether the answer is ours: in plain doubles, or, for a hit, the exact one. */
        default boolean isOurs() {
            return answerIs(OURS);
        }

        double roughness();

        /** Whether the answer differs from ours where an image shows it: any but a colour within a level. */
        default boolean visible() {
            return true;
        }

        /** "for INPUT, yours is X; ours is Y". */
        String counterexample();

        /**
         * Whether the answer may be one the code gives when its image is that of {@code render}, a mistake
         * of render drawn with our answers: unless a model of the answers says otherwise, it may.
         */
        default boolean couldBeDrawnWith(Variant render) {
            return true;
        }
    }

    static Behaviour judge(Answers answers) {
        // A log that ends for want of a thread holds no answer to the calls never made. Those cannot be compared,
        // and a method judged on part of its inputs would not be judged as every other student's is: no finding.
        if (!answers.any() || answers.noThread()) {
            MethodBehaviour none = new MethodBehaviour("", 0, MethodBehaviour.Difference.NONE, List.of(), List.of(),
                    List.of());
            return new Behaviour(false, none, none);
        }
        List<RayCase> rays = new ArrayList<>();
        for (BehaviourInputs.IntersectionCall call : BehaviourInputs.INTERSECTIONS) {
            if (!UNTESTED_EDGES.contains(call.name())) {
                rays.add(new RayCase(call, answers.get(call.name())));
            }
        }
        BehaviourInputs.RANDOM_INTERSECTIONS.forEach(call -> rays.add(new RayCase(call, answers.get(call.name()))));
        List<ShadeCase> shadings = new ArrayList<>();
        BehaviourInputs.ILLUMINATIONS.forEach(call -> shadings.add(new ShadeCase(call, answers.get(call.name()),
                BehaviourInputs.Phong.FIXED)));
        BehaviourInputs.RANDOM_ILLUMINATIONS.forEach(call -> shadings.add(new ShadeCase(call,
                answers.get(call.name()), answers.phong())));
        MethodBehaviour intersection = judge("intersectionWith", rays, Variant.Method.INTERSECTION_WITH,
                AnswerFacts.ofHits(rays));
        intersection = new MethodBehaviour(intersection.method(), intersection.inputs(), intersection.difference(),
                untested(answers, rays, intersection.difference().mistake()), intersection.ruledOut(),
                intersection.notAlone());
        MethodBehaviour illumination = judge("illuminate", shadings, Variant.Method.ILLUMINATE,
                AnswerFacts.ofColours(shadings));
        return new Behaviour(true, intersection, illumination);
    }

    static MethodBehaviour judge(String method, List<? extends Case> cases, Variant.Method which,
            List<String> properties) {
        List<Integer> differing = IntStream.range(0, cases.size()).filter(i -> !cases.get(i).isOurs()).boxed()
                .toList();
        List<Variant> ruledOut = mistakes(which).stream()
                .filter(v -> !everyAnswer(cases, c -> c.answerIs(EnumSet.of(v)))).toList();
        if (differing.isEmpty()) {
            return new MethodBehaviour(method, cases.size(), MethodBehaviour.Difference.NONE, List.of(), ruledOut,
                    List.of());
        }
        List<Variant> notAlone = Stream.of(Variant.values()).filter(v -> v.method() == Variant.Method.RENDER
                && differing.stream().map(cases::get).anyMatch(c -> c.visible() && !c.couldBeDrawnWith(v))).toList();
        // The differing inputs first: a model that is not the student's fails on one of them at once.
        List<Case> order = new ArrayList<>();
        differing.forEach(i -> order.add(cases.get(i)));
        IntStream.range(0, cases.size()).filter(i -> !differing.contains(i)).forEach(i -> order.add(cases.get(i)));
        // The simplest input a student can see in an image; else the simplest, said to be invisible.
        Comparator<Case> simplestFirst = Comparator.comparingDouble(Case::roughness);
        String counterexample = differing.stream().map(cases::get).filter(Case::visible).min(simplestFirst)
                .map(Case::counterexample)
                .orElseGet(() -> differing.stream().map(cases::get).min(simplestFirst).orElseThrow().counterexample()
                        + " (" + BELOW_ONE_LEVEL + ")");
        return new MethodBehaviour(method, cases.size(), new MethodBehaviour.Difference(differing,
                reproducing(order, which), counterexample, properties), List.of(), ruledOut, notAlone);
    }

    /** The catalogue's mistakes of the method {@code which}: the entries with a model of it, but ours. */
    private static List<Variant> mistakes(Variant.Method which) {
        return Stream.of(Variant.values()).filter(v -> v.method() == which && !v.isCorrect()).toList();
    }

    /**
     * The catalogue's entries whose model gives every answer: one, or two together, or none. Two
     * entries that each give every answer alone are equally the explanation: naming one would lead
     * with it, so neither is named and the facts are given (the catalogue names a known tie as one
     * entry).
     */
    static List<Variant> reproducing(List<? extends Case> cases, Variant.Method which) {
        List<Variant> models = mistakes(which);
        List<Variant> alone = models.stream().filter(v -> everyAnswer(cases, c -> c.answerIs(EnumSet.of(v))))
                .toList();
        if (!alone.isEmpty()) {
            return alone.size() == 1 ? alone : List.of();
        }
        for (int i = 0; i < models.size(); i++) {
            for (int j = i + 1; j < models.size(); j++) {
                Set<Variant> pair = EnumSet.of(models.get(i), models.get(j));
                if (everyAnswer(cases, c -> c.answerIs(pair))) {
                    return List.copyOf(pair);
                }
            }
        }
        return List.of();
    }

    private static boolean everyAnswer(List<? extends Case> cases, Predicate<Case> test) {
        for (Case c : cases) {
            if (!test.test(c)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The notes on the edge cases the course's scenes cannot show: none where the answer is ours
     * or the handout's six steps' (a correct answer too).
     */
    private static List<String> untested(Answers answers, List<RayCase> tested, List<Variant> testedMistake) {
        List<String> notes = new ArrayList<>();
        List<RayCase> every = new ArrayList<>(tested);
        List<RayCase> edges = new ArrayList<>();
        for (BehaviourInputs.IntersectionCall call : BehaviourInputs.INTERSECTIONS) {
            if (UNTESTED_EDGES.contains(call.name())) {
                edges.add(new RayCase(call, answers.get(call.name())));
            }
        }
        every.addAll(0, edges);
        Set<Variant> literal = EnumSet.of(Variant.HANDOUT_SIX_STEPS);
        for (RayCase edge : edges) {
            // Nothing to add where the answer is a correct one, or the tested finding's model gives it too.
            if (edge.isOurs() || edge.answerIs(literal)
                    || !testedMistake.isEmpty() && edge.answerIs(EnumSet.copyOf(testedMistake))) {
                continue;
            }
            List<Variant> named = reproducing(every, Variant.Method.INTERSECTION_WITH);
            Models.Hit handout = edge.model(literal);
            notes.add(UNTESTED + ": for " + situation(edge.call().name()) + " (" + Words.ray(edge.call())
                    + "), your intersectionWith returns " + Words.hit(edge.answer()) + "; ours returns "
                    + Words.hit(edge.model(OURS)) + ", the nearest root with s > 0"
                    + (handout == null ? ", and the handout's six steps return no hit, also a correct answer" : "")
                    + (named.isEmpty() ? "" : "; every answer of yours is that of \"" + titles(named) + "\""));
        }
        return notes;
    }

    private static String situation(String edge) {
        return switch (edge) {
            case "graze" -> "a ray that grazes a sphere";
            case "inside" -> "a ray that starts inside a sphere";
            default -> "a ray that starts on a sphere's surface";
        };
    }

    static String titles(List<Variant> variants) {
        return String.join("\" with \"", variants.stream().map(Variant::title).toList());
    }

    /** A ray, a sphere and what intersectionWith gave. */
    record RayCase(BehaviourInputs.IntersectionCall call, Answer answer) implements Case {

        Models.Hit model(Set<Variant> variants) {
            return Models.intersect(v(call.origin()), v(call.direction()), v(call.centre()), call.radius(),
                    variants);
        }

        @Override
        public boolean answerIs(Set<Variant> variants) {
            return same(model(variants));
        }

        @Override
        public boolean isOurs() {
            if (answerIs(OURS)) {
                return true;
            }
            RaycastHit exact = Intersection.ROBUST.find(new Sphere(v(call.centre()), call.radius(), new Vector3(1)),
                    new Ray(v(call.origin()), v(call.direction())));
            return same(exact.getObjectHit() == null ? null
                    : new Models.Hit(exact.getDistance(), exact.getLocation(), exact.getNormal()));
        }

        private boolean same(Models.Hit expected) {
            if (expected == null || answer instanceof None) {
                return expected == null && answer instanceof None;
            }
            if (!(answer instanceof Hit hit) || !hit.sameSphere()) {
                return false;
            }
            double size = Math.max(1, Math.max(Math.max(length(call.origin()), length(call.centre())), call.radius()));
            double along = length(call.direction());
            return close(hit.distance() * along, expected.distance() * along, size)
                    && close(hit.point(), expected.point(), size)
                    && close(hit.normal(), expected.normal(), Math.max(1, size / call.radius()));
        }

        /** The input's roughness and our answer's: the simplest counterexample has round numbers in both. */
        @Override
        public double roughness() {
            Models.Hit ours = model(OURS);
            return Words.roughness(call) + (ours == null ? 0 : Words.roughness(ours.distance(),
                    ours.point().x, ours.point().y, ours.point().z));
        }

        @Override
        public String counterexample() {
            return "for " + Words.ray(call) + ", " + Words.yoursAndOurs(digits -> Words.hit(answer, digits),
                    digits -> Words.hit(model(OURS), digits));
        }
    }

    /** A point to shade and what illuminate gave. */
    record ShadeCase(BehaviourInputs.IlluminationCall call, Answer answer, BehaviourInputs.Phong phong)
            implements Case {

        Vector3 model(Set<Variant> variants) {
            boolean set = phong == BehaviourInputs.Phong.SET;
            BehaviourInputs.LightInput light = call.light();
            BehaviourInputs.Material material = call.sphere().material();
            return Models.illuminate(new Models.Shading(v(call.ambient()),
                    new PointLight(v(light.position()), v(light.colour()), light.intensity()),
                    new Models.Surface(v(material.colour()), set ? material.kD() : BehaviourInputs.COURSE_KD,
                            set ? material.kS() : BehaviourInputs.COURSE_KS,
                            set ? material.n() : BehaviourInputs.COURSE_N),
                    v(call.point()), v(call.normal())), variants);
        }

        @Override
        public boolean answerIs(Set<Variant> variants) {
            if (!(answer instanceof Colour colour)) {
                return false;
            }
            Vector3 expected = model(variants);
            double[] rgb = colour.rgb();
            return closeClamped(rgb[0], expected.x) && closeClamped(rgb[1], expected.y)
                    && closeClamped(rgb[2], expected.z);
        }

        @Override
        public double roughness() {
            Vector3 ours = model(OURS);
            return Words.roughness(call) + Words.roughness(ours.x, ours.y, ours.z);
        }

        @Override
        public boolean visible() {
            if (!(answer instanceof Colour colour)) {
                return true;
            }
            Vector3 ours = model(OURS);
            double[] rgb = colour.rgb();
            return Vector3.toByte(rgb[0]) != Vector3.toByte(ours.x) || Vector3.toByte(rgb[1]) != Vector3.toByte(ours.y)
                    || Vector3.toByte(rgb[2]) != Vector3.toByte(ours.z) || Double.isNaN(rgb[0] + rgb[1] + rgb[2]);
        }

        /**
         * Our colour, exchanged red for blue where the image's red and blue are (the exchange may be made here),
         * or within a level of ours where the image is rounded (a rounding here gives that): no other.
         */
        @Override
        public boolean couldBeDrawnWith(Variant render) {
            if (!(answer instanceof Colour colour)) {
                return false;
            }
            Vector3 ours = model(OURS);
            double[] rgb = colour.rgb();
            return switch (render) {
                case RED_BLUE_SWAPPED -> closeClamped(rgb[0], ours.z) && closeClamped(rgb[1], ours.y)
                        && closeClamped(rgb[2], ours.x);
                case ROUNDED_BYTES -> Math.abs(Vector3.toByte(rgb[0]) - Vector3.toByte(ours.x)) <= 1
                        && Math.abs(Vector3.toByte(rgb[1]) - Vector3.toByte(ours.y)) <= 1
                        && Math.abs(Vector3.toByte(rgb[2]) - Vector3.toByte(ours.z)) <= 1;
                default -> false;
            };
        }

        @Override
        public String counterexample() {
            return "for " + Words.shading(call, phong) + ", " + Words.yoursAndOurs(
                    digits -> Words.colour(answer, digits), digits -> Words.colour(model(OURS), digits));
        }
    }

    static Vector3 v(double[] xyz) {
        return new Vector3(xyz[0], xyz[1], xyz[2]);
    }

    static double length(double[] v) {
        return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }

    private static boolean close(double a, double b, double size) {
        return Math.abs(a - b) <= TOLERANCE * size; // false for NaN
    }

    private static boolean close(double[] a, Vector3 b, double size) {
        return close(a[0], b.x, size) && close(a[1], b.y, size) && close(a[2], b.z, size);
    }

    /** Two channels after the clamp to [0, 1] that toRGB() applies; NaN is never close. */
    private static boolean closeClamped(double a, double b) {
        return close(Math.max(0, Math.min(1, a)), Math.max(0, Math.min(1, b)), 1) && !Double.isNaN(a)
                && !Double.isNaN(b);
    }
}
