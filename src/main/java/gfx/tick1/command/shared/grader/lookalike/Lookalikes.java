package gfx.tick1.command.shared.grader.lookalike;

import gfx.tick1.command.shared.grader.lookalike.GreedyStringTiling.Tile;
import gfx.tick1.command.shared.grader.lookalike.Lookalike.Reason;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.command.shared.grader.model.Submission;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.IntStream;

/**
 * Which submissions of a cohort look alike: every pair compared in tokens ({@link CodeReader},
 * {@link GreedyStringTiling}), every submission against tick1's reference, and the failed ones by
 * their wrong answers ({@link WrongAnswers}). Correct code of a two-method tick converges, so a
 * look-alike is a reason to talk with the students, never a verdict.
 */
public final class Lookalikes {

    /**
     * The shortest shared run that counts, in tokens: about one statement
     * ({@code Vector3 # = #.scale(-1).normalised();} is 15). Chosen on independent solutions and
     * planted copies: see docs/grading.md.
     */
    public static final int MINIMUM_MATCH = 12;
    /** The least similarity of a pair listed for its tokens, and of a submission flagged as like the reference. */
    public static final double TOKEN_THRESHOLD = 0.8;
    /** The most pairs listed; the most similar are kept. */
    public static final int MOST_PAIRS = 1_000;
    /** One in how many of the cohort may share wrong answers for their pairs to be listed: rarer is telling. */
    static final int RARE = 50;
    /** The identifier of tick1's reference in place of a student's. */
    public static final String REFERENCE = "tick1 reference";

    /** The stack of the threads that parse: JavaParser recurses through the tree, as in {@code tick1 diff}. */
    private static final long DEEP_STACK = 256L << 20;

    private Lookalikes() {
    }

    /**
     * The look-alikes among {@code results}, most similar first: pairs whose tokens are alike, submissions
     * like the reference, and pairs with the same rare wrong answers; at most {@link #MOST_PAIRS}.
     */
    public static List<Lookalike> find(List<StudentResult> results) throws InterruptedException {
        return find(results, ParsedCodes.NONE);
    }

    /**
     * As {@link #find(List)}, taking each file parsed before from {@code parsed}, and keeping there those parsed now:
     * the look-alikes are the same.
     */
    public static List<Lookalike> find(List<StudentResult> results, ParsedCodes parsed) throws InterruptedException {
        CodeReader reader = new CodeReader(MINIMUM_MATCH, parsed);
        List<StudentResult> compared = results.stream().filter(r -> r.submission().problem() == null).toList();
        List<ComparedCode> codes = read(reader, compared);
        List<Lookalike> found = Collections.synchronizedList(new ArrayList<>());
        IntStream.range(0, codes.size()).parallel().forEach(i -> {
            for (int j = i + 1; j < codes.size(); j++) {
                Comparison pair = Comparison.of(codes.get(i), codes.get(j));
                double similarity = pair.similarity();
                if (similarity >= TOKEN_THRESHOLD) {
                    found.add(new Lookalike(compared.get(i).submission(), compared.get(j).submission(),
                            Reason.TOKENS, "same tokens after renaming (" + percent(similarity) + ")", pair));
                }
            }
            Comparison withReference = Comparison.of(codes.get(i), reader.reference());
            double similarity = withReference.similarity();
            if (similarity >= TOKEN_THRESHOLD) {
                found.add(new Lookalike(compared.get(i).submission(), null, Reason.REFERENCE,
                        "like tick1's reference: same tokens after renaming (" + percent(similarity) + ")",
                        withReference));
            }
        });
        found.addAll(sameWrongAnswers(compared, codes, results.size()));
        List<Lookalike> sorted = new ArrayList<>(found);
        sorted.sort(Comparator.comparingDouble(Lookalike::similarity).reversed()
                .thenComparing(Lookalike::reason)
                .thenComparing(pair -> pair.a().id())
                .thenComparing(pair -> pair.b() == null ? "" : pair.b().id()));
        return List.copyOf(sorted.subList(0, Math.min(MOST_PAIRS, sorted.size())));
    }

    /** The share of both sides' counted tokens that lie in tiles; 0 when either side has none. */
    static double similarity(ComparedCode a, ComparedCode b, List<Tile> tiles) {
        int counted = a.counted() + b.counted();
        if (a.counted() == 0 || b.counted() == 0) {
            return 0;
        }
        return 2.0 * tiles.stream().mapToInt(Tile::length).sum() / counted;
    }

    /** A share as a whole percentage, rounded down, so that 99.6% of the tokens never reads as 100%. */
    public static String percent(double share) {
        return String.format(Locale.ROOT, "%.0f%%", Math.floor(100 * share));
    }

    /**
     * The pairs whose failed submissions share a fingerprint of wrong answers that at most one in
     * {@link #RARE} of the cohort (and at least two) share: the same wrong code, or the same slip.
     */
    private static List<Lookalike> sameWrongAnswers(List<StudentResult> compared, List<ComparedCode> codes,
            int cohort) {
        Map<List<String>, List<Integer>> byAnswers = new LinkedHashMap<>();
        Map<List<String>, WrongAnswers> fingerprints = new LinkedHashMap<>();
        for (int i = 0; i < compared.size(); i++) {
            WrongAnswers answers = WrongAnswers.of(compared.get(i));
            if (answers != null) {
                byAnswers.computeIfAbsent(answers.answers(), key -> new ArrayList<>()).add(i);
                fingerprints.putIfAbsent(answers.answers(), answers);
            }
        }
        int most = Math.max(2, cohort / RARE);
        List<Lookalike> pairs = new ArrayList<>();
        byAnswers.forEach((answers, students) -> {
            if (students.size() > most) {
                return;
            }
            WrongAnswers fingerprint = fingerprints.get(answers);
            for (int x = 0; x < students.size(); x++) {
                for (int y = x + 1; y < students.size(); y++) {
                    int i = students.get(x);
                    int j = students.get(y);
                    pairs.add(new Lookalike(compared.get(i).submission(), compared.get(j).submission(),
                            fingerprint.isNamed() ? Reason.SAME_WRONG_ANSWERS : Reason.SAME_UNCATALOGUED_ANSWERS,
                            fingerprint.why(), Comparison.of(codes.get(i), codes.get(j))));
                }
            }
        });
        return pairs;
    }

    /** Each submission's code, read on threads with a deep stack (two at most: the grader shares the machine). */
    private static List<ComparedCode> read(CodeReader reader, List<StudentResult> results)
            throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(Math.min(2, Runtime.getRuntime().availableProcessors()),
                task -> {
                    Thread thread = new Thread(null, task, "tick1 look-alikes", DEEP_STACK);
                    thread.setDaemon(true);
                    return thread;
                });
        try {
            List<Future<ComparedCode>> futures = new ArrayList<>();
            for (StudentResult result : results) {
                Submission submission = result.submission();
                futures.add(pool.submit(() -> reader.read(text(submission.sphere()), text(submission.renderer()))));
            }
            List<ComparedCode> codes = new ArrayList<>();
            for (Future<ComparedCode> future : futures) {
                codes.add(future.get());
            }
            return codes;
        } catch (ExecutionException e) {
            throw new IllegalStateException("reading a submission for comparing failed", e.getCause());
        } finally {
            pool.shutdownNow();
        }
    }

    private static String text(Submission.SourceFile file) {
        return file == null ? null : new String(file.content(), StandardCharsets.UTF_8);
    }
}
