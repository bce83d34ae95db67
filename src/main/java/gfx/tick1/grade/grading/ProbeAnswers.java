package gfx.tick1.grade.grading;

import gfx.tick1.grade.harness.ProbeCalls;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What the student's methods answered on each of {@link ProbeCalls}, parsed from the log the child
 * wrote. The log is the student's process's, so it is read strictly: only lines of the harness's
 * form, for names of calls that exist, each name once (later lines for a name are ignored), and
 * at most a few hundred lines; anything else counts as no answer. What the code could forge this
 * way is only which of the grader's own fixed sentences it gets.
 */
final class ProbeAnswers {

    /** What one call gave. */
    sealed interface Answer {
    }

    /** A hit: whether it names the sphere called, its distance, point and normal. */
    record Hit(boolean sameSphere, double distance, double[] point, double[] normal) implements Answer {
    }

    /** An empty RaycastHit: no sphere. */
    record None() implements Answer {
    }

    /** illuminate's colour. */
    record Colour(double[] rgb) implements Answer {
    }

    /** No answer: null, an exception, no return within the time, no such method, or nothing logged. */
    record Failed(String how) implements Answer {
    }

    /** Every call's line, the phong line, and a few to spare. */
    private static final int MAX_LINES = ProbeCalls.INTERSECTIONS.size() + ProbeCalls.ILLUMINATIONS.size()
            + 2 * ProbeCalls.RANDOM_COUNT + 10;
    private static final String NUMBER = "(-?(?:\\d{1,20}(?:\\.\\d{0,20})?(?:E-?\\d{1,3})?|Infinity)|NaN)";
    private static final Pattern PHONG = Pattern.compile("phong (set|fixed)");
    private static final Pattern LINE = Pattern.compile("([a-z][a-z0-9-]{0,19}) (?:hit ([01])((?: " + NUMBER + "){7})"
            + "|(none)|colour((?: " + NUMBER + "){3})|(null|threw|timeout|absent))");

    private final Map<String, Answer> answers = new HashMap<>();
    /** Whether the random shadings' k_d, k_s and n were set on the student's spheres (else the course's). */
    private Boolean phongSet;

    private ProbeAnswers() {
    }

    /** The answers in {@code log} (null when the child left none). */
    static ProbeAnswers parse(String log) {
        ProbeAnswers parsed = new ProbeAnswers();
        if (log == null) {
            return parsed;
        }
        Set<String> names = new HashSet<>();
        ProbeCalls.INTERSECTIONS.forEach(call -> names.add(call.name()));
        ProbeCalls.ILLUMINATIONS.forEach(call -> names.add(call.name()));
        ProbeCalls.RANDOM_INTERSECTIONS.forEach(call -> names.add(call.name()));
        ProbeCalls.RANDOM_ILLUMINATIONS.forEach(call -> names.add(call.name()));
        log.lines().limit(MAX_LINES).forEach(line -> {
            Matcher phong = PHONG.matcher(line);
            if (phong.matches() && parsed.phongSet == null) {
                parsed.phongSet = phong.group(1).equals("set");
                return;
            }
            Matcher m = LINE.matcher(line);
            if (m.matches() && names.contains(m.group(1)) && !parsed.answers.containsKey(m.group(1))) {
                parsed.answers.put(m.group(1), answer(m));
            }
        });
        return parsed;
    }

    private static Answer answer(Matcher m) {
        if (m.group(2) != null) {
            double[] numbers = numbers(m.group(3));
            return new Hit(m.group(2).equals("1"), numbers[0], new double[] {numbers[1], numbers[2], numbers[3]},
                    new double[] {numbers[4], numbers[5], numbers[6]});
        }
        if (m.group(5) != null) {
            return new None();
        }
        if (m.group(6) != null) {
            return new Colour(numbers(m.group(6)));
        }
        return new Failed(m.group(8));
    }

    private static double[] numbers(String text) {
        String[] words = text.strip().split(" ");
        double[] values = new double[words.length];
        for (int i = 0; i < words.length; i++) {
            values[i] = Double.parseDouble(words[i]);
        }
        return values;
    }

    /** Whether the log held any answer at all: without one, the probes did not run. */
    boolean any() {
        return !answers.isEmpty();
    }

    /** Whether the random shadings' spheres had their k_d, k_s and n set (else they kept the course's). */
    boolean phongSet() {
        return Boolean.TRUE.equals(phongSet);
    }

    /** The answer to the call {@code name}; "missing" when none was logged. */
    Answer get(String name) {
        return answers.getOrDefault(name, new Failed("missing"));
    }
}
