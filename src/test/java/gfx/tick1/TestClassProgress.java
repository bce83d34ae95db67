package gfx.tick1;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * One line per test class as it finishes (its tests, failures, skips and seconds), and each failure as it happens,
 * so that a long test run shows where it is; at the end, the run's counts, each skipped test with the reason it was
 * skipped, and the ten slowest classes with their times (each from its start to its end: with classes run side by
 * side, these can add up to more than the run). A test whose assumption does not hold (no course figures, root may
 * write anywhere) is one the JUnit Platform calls "aborted": it was not run, so it is counted and named here as
 * skipped, with the assumption's words.
 * The JUnit console launcher that runs the tests on Gradle 4.4.1 prints its tree only once every test has run;
 * Gradle 9's own test logging streams already, so this prints only when the system property
 * {@code tick1.testProgress} is {@code true}. Found by the JUnit Platform through {@code META-INF/services}. Test
 * classes run side by side (junit-platform.properties), so the Platform may call it from several threads at once.
 */
public final class TestClassProgress implements TestExecutionListener {

    private final boolean on;
    private final PrintStream out;
    private final Map<String, long[]> counts = new HashMap<>();   // class id -> {tests, failed, skipped, start}
    private final List<String> skipped = new ArrayList<>();       // "Class test: reason", in the order skipped
    private final Map<String, Double> classSeconds = new HashMap<>();   // class -> seconds from start to end
    private TestPlan plan;
    private int classesDone;
    private long tests;
    private long failures;
    private long skippedTests;
    private long start;

    /** As the JUnit Platform makes it: on when the system property {@code tick1.testProgress} is true. */
    public TestClassProgress() {
        this(System.out, Boolean.getBoolean("tick1.testProgress"));
    }

    TestClassProgress(PrintStream out, boolean on) {
        this.out = out;
        this.on = on;
    }

    /** How many of the slowest classes the closing summary lists. */
    static final int SLOWEST_SHOWN = 10;

    @Override
    public synchronized void testPlanExecutionStarted(TestPlan testPlan) {
        plan = testPlan;
        start = System.nanoTime();
    }

    @Override
    public synchronized void testPlanExecutionFinished(TestPlan testPlan) {
        if (!on) {
            return;
        }
        out.println(String.format(Locale.ROOT, "%d tests in %.0f s: %d passed, %d failed, %d skipped", tests,
                (System.nanoTime() - start) / 1e9, tests - failures - skippedTests, failures, skippedTests));
        if (!skipped.isEmpty()) {
            out.println("Skipped, and why:");
            skipped.forEach(line -> out.println("  " + line));
        }
        if (!classSeconds.isEmpty()) {
            out.println("Slowest classes:");
            classSeconds.entrySet().stream()
                    .sorted(Map.Entry.<String, Double>comparingByValue().reversed()
                            .thenComparing(Map.Entry.comparingByKey()))
                    .limit(SLOWEST_SHOWN)
                    .forEach(slow -> out.println(String.format(Locale.ROOT, "  %7.1f s  %s", slow.getValue(),
                            slow.getKey())));
        }
        out.flush();
    }

    @Override
    public synchronized void executionStarted(TestIdentifier id) {
        if (on && isTestClass(id)) {
            counts.put(id.getUniqueId(), new long[] {0, 0, 0, System.nanoTime()});
        }
    }

    @Override
    public synchronized void executionSkipped(TestIdentifier id, String reason) {
        if (on) {
            long count = id.isTest() ? 1 : Math.max(1, plan.getDescendants(id).stream().filter(TestIdentifier::isTest)
                    .count());
            testClassOf(id).ifPresent(c -> counts.computeIfAbsent(c.getUniqueId(), k -> new long[4])[2] += count);
            tests += count;
            skippedTests += count;
            String tally = id.isTest() ? "" : " (" + count + (count == 1 ? " test)" : " tests)");
            skipped.add(name(id) + tally + ": " + reason);
            if (isTestClass(id)) {
                print(id);
            }
        }
    }

    @Override
    public synchronized void executionFinished(TestIdentifier id, TestExecutionResult result) {
        if (!on) {
            return;
        }
        boolean failed = result.getStatus() == TestExecutionResult.Status.FAILED;
        // An assumption that does not hold (root may write anywhere, no course figures) aborts a test: it is
        // counted with the skipped ones, as the launcher's own summary counts it apart from the failures.
        boolean aborted = result.getStatus() == TestExecutionResult.Status.ABORTED;
        if (id.isTest()) {
            tests++;
            failures += failed ? 1 : 0;
            if (aborted) {
                skippedTests++;
                skipped.add(name(id) + ": " + result.getThrowable().map(TestClassProgress::assumption).orElse("?"));
            }
            testClassOf(id).ifPresent(c -> {
                long[] count = counts.computeIfAbsent(c.getUniqueId(), k -> new long[4]);
                count[0]++;
                count[1] += failed ? 1 : 0;
                count[2] += aborted ? 1 : 0;
            });
        }
        if (failed) {
            out.println("  FAILED " + id.getDisplayName() + ": " + result.getThrowable()
                    .map(t -> String.valueOf(t.getMessage()).strip().lines().findFirst().orElse(""))
                    .orElse(""));
        }
        if (isTestClass(id)) {
            print(id);
        }
    }

    private void print(TestIdentifier testClass) {
        long[] count = counts.getOrDefault(testClass.getUniqueId(), new long[4]);
        double seconds = count[3] == 0 ? 0 : (System.nanoTime() - count[3]) / 1e9;
        classesDone++;
        String className = ((ClassSource) testClass.getSource().orElseThrow()).getClassName().replace("gfx.tick1.", "");
        classSeconds.put(className, seconds);
        out.println(String.format(Locale.ROOT, "%4d  %-58s %4d test%s%s%s %7.1f s", classesDone, className,
                count[0], count[0] == 1 ? " " : "s", count[1] > 0 ? ", " + count[1] + " FAILED" : "",
                count[2] > 0 ? ", " + count[2] + " skipped" : "", seconds));
        out.flush();
    }

    /** "ClassName test()": the test's class without the common package, and its display name. */
    private String name(TestIdentifier id) {
        String className = testClassOf(id).flatMap(TestIdentifier::getSource).map(source -> ((ClassSource) source)
                .getClassName().replace("gfx.tick1.", "")).orElse("");
        return isTestClass(id) ? className : className + " " + id.getDisplayName();
    }

    /** The words of an assumption that did not hold, without JUnit's "Assumption failed: " and a "skipped: ". */
    private static String assumption(Throwable aborted) {
        return String.valueOf(aborted.getMessage()).replaceFirst("^Assumption failed: ", "")
                .replaceFirst("^skipped: ", "").strip();
    }

    /** A top-level test class (not a nested one, whose tests count for the class around it). */
    private boolean isTestClass(TestIdentifier id) {
        return id.getSource().filter(ClassSource.class::isInstance).isPresent()
                && plan.getParent(id).flatMap(TestIdentifier::getSource).filter(ClassSource.class::isInstance)
                        .isEmpty();
    }

    private Optional<TestIdentifier> testClassOf(TestIdentifier id) {
        Optional<TestIdentifier> at = Optional.of(id);
        while (at.isPresent() && !isTestClass(at.get())) {
            at = plan.getParent(at.get());
        }
        return at;
    }
}
