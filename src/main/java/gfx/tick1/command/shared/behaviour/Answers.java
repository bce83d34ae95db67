package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.grader.harness.AnswerLog;
import gfx.tick1.command.shared.grader.harness.BehaviourInputs;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/**
 * What the student's methods answered on each of {@link BehaviourInputs}, parsed from the log the child
 * wrote. The log is the student's process's, so it is read strictly: only lines of the harness's
 * form, for names of calls that exist, each name once (later lines for a name are ignored), and
 * at most a few hundred lines; anything else counts as no answer. What the code could forge this
 * way is only which of the grader's own fixed sentences it gets.
 */
final class Answers {

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
    private static final int MAX_LINES = BehaviourInputs.INTERSECTIONS.size() + BehaviourInputs.ILLUMINATIONS.size()
            + 2 * BehaviourInputs.RANDOM_COUNT + 10;
    /** The longest number the harness writes: Double.toString's, with room to spare. */
    private static final int NUMBER_CHARS = 26;

    private final Map<String, Answer> answers = new HashMap<>();
    /** Whether the random shadings' k_d, k_s and n were set on the student's spheres (else the course's). */
    private BehaviourInputs.Phong phong;
    /** Whether the log says that a call found no thread to run in, so the calls left were never made. */
    private boolean noThread;

    private Answers() {
    }

    /**
     * The answers in {@code log} (null when the child left none), read word by word: a few
     * thousand lines, so no backtracking pattern is run on them.
     */
    static Answers parse(String log) {
        Set<String> names = new HashSet<>();
        BehaviourInputs.INTERSECTIONS.forEach(call -> names.add(call.name()));
        BehaviourInputs.ILLUMINATIONS.forEach(call -> names.add(call.name()));
        BehaviourInputs.RANDOM_INTERSECTIONS.forEach(call -> names.add(call.name()));
        BehaviourInputs.RANDOM_ILLUMINATIONS.forEach(call -> names.add(call.name()));
        return parse(log, names, MAX_LINES);
    }

    /** The answers in {@code log} to the inputs the grader chose, {@code chosen}, alone. */
    static Answers parse(String log, BehaviourInputs.Chosen chosen) {
        Set<String> names = new HashSet<>();
        chosen.intersections().forEach(call -> names.add(call.name()));
        chosen.illuminations().forEach(call -> names.add(call.name()));
        return parse(log, names, names.size() + 10);
    }

    private static Answers parse(String log, Set<String> names, int maxLines) {
        Answers parsed = new Answers();
        if (log == null) {
            return parsed;
        }
        log.lines().limit(maxLines).forEach(line -> {
            if (line.equals(AnswerLog.NO_THREAD)) {
                parsed.noThread = true;
                return;
            }
            String[] words = line.split(" ", 12);
            if (words.length == 2 && words[0].equals("phong") && parsed.phong == null) {
                for (BehaviourInputs.Phong phong : BehaviourInputs.Phong.values()) {
                    if (words[1].equals(phong.word())) {
                        parsed.phong = phong;
                        return;
                    }
                }
            }
            if (names.contains(words[0]) && !parsed.answers.containsKey(words[0])) {
                Answer answer = answer(words);
                if (answer != null) {
                    parsed.answers.put(words[0], answer);
                }
            }
        });
        return parsed;
    }

    /** The answer a line's words give, or null when they are not one of the harness's forms. */
    private static Answer answer(String[] words) {
        if (words.length == 10 && words[1].equals("hit") && (words[2].equals("0") || words[2].equals("1"))) {
            double[] n = numbers(words, 3, 7);
            return n == null ? null : new Hit(words[2].equals("1"), n[0], new double[] {n[1], n[2], n[3]},
                    new double[] {n[4], n[5], n[6]});
        }
        if (words.length == 5 && words[1].equals("colour")) {
            double[] n = numbers(words, 2, 3);
            return n == null ? null : new Colour(n);
        }
        if (words.length == 2) {
            return switch (words[1]) {
                case "none" -> new None();
                case "null", "threw", "timeout", "absent" -> new Failed(words[1]);
                default -> null;
            };
        }
        return null;
    }

    /** {@code count} numbers from {@code from}, each as Double.toString writes one; null if one is not. */
    private static double[] numbers(String[] words, int from, int count) {
        double[] values = new double[count];
        for (int i = 0; i < count; i++) {
            String word = words[from + i];
            boolean special = word.equals("NaN") || word.equals("Infinity") || word.equals("-Infinity");
            if (word.isEmpty() || word.length() > NUMBER_CHARS || !special && !word.chars().allMatch(c -> c >= '0'
                    && c <= '9' || c == '.' || c == 'E' || c == '-')) {
                return null;
            }
            try {
                values[i] = Double.parseDouble(word);
            } catch (NumberFormatException e) {
                return null;
            }
        }
        return values;
    }

    /** Whether the log held any answer at all: without one, the probes did not run. */
    boolean any() {
        return !answers.isEmpty();
    }

    /**
     * Whether a call found no thread to run in (the program had reached the limit of processes and threads), so
     * the calls after it were never made.
     */
    boolean noThread() {
        return noThread;
    }

    /** Whether the random shadings' spheres had their k_d, k_s and n set (else they kept the course's). */
    BehaviourInputs.Phong phong() {
        return phong == null ? BehaviourInputs.Phong.FIXED : phong;
    }

    /** The answer to the call {@code name}; "missing" when none was logged. */
    Answer get(String name) {
        return answers.getOrDefault(name, new Failed("missing"));
    }
}
