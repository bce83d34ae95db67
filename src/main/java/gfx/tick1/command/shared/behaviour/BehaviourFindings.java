package gfx.tick1.command.shared.behaviour;

import gfx.tick1.engine.io.Counted;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

/**
 * What the behaviour comparison found, in the words every report uses: for each method that
 * does not behave as ours, one tested finding (the catalogue's mistake whose model gives every
 * answer, or the simplest counterexample and what the answers show); then the notes on what the
 * course's scenes cannot show, always after the tested findings and always with the one label
 * {@link BehaviourJudge#UNTESTED}; the sections to reread, at most three.
 */
public final class BehaviourFindings {

    /** The most sections a report lists to reread. */
    static final int SECTIONS = 3;

    private static final String INTERSECTION_SECTION = "section 4, \"Ray-sphere intersection code\"";
    private static final String ILLUMINATE_SECTION = "section 5, \"Phong illumination code\"";

    /** One method's tested finding: the fact, the section to reread, and the cohort chart's label. */
    record Finding(String method, String fact, String section, String label) {
    }

    /** Why the probes did not run when a call found no thread to run in. */
    private static final String NO_THREAD = "the program reached the limit of processes and threads, so no thread "
            + "was left to call your methods in";

    private final Behaviour behaviour;
    /** Whether a call found no thread to run in, the program being at the limit of processes and threads. */
    private final boolean noThread;
    private final List<Finding> tested = new ArrayList<>();

    private BehaviourFindings(Behaviour behaviour, boolean noThread) {
        this.behaviour = behaviour;
        this.noThread = noThread;
        if (behaviour.ran()) {
            Stream.of(behaviour.intersectionWith(), behaviour.illuminate()).filter(b -> !b.behavesAsOurs())
                    .forEach(b -> tested.add(finding(b)));
        }
    }

    /** The findings of the probes' log {@code log} (null when the child left none). */
    public static BehaviourFindings of(String log) {
        Answers answers = Answers.parse(log);
        return new BehaviourFindings(BehaviourJudge.judge(answers), answers.noThread());
    }

    private static Finding finding(MethodBehaviour b) {
        String inputs = Counted.of(b.inputs(), "input");
        boolean sphere = b.method().equals("intersectionWith");
        MethodBehaviour.Difference d = b.difference();
        if (!d.mistake().isEmpty()) {
            List<String> explained = d.mistake().stream().map(Variant::explanation).toList();
            return new Finding(b.method(), "your " + b.method() + " gives the answers of \""
                    + BehaviourJudge.titles(d.mistake()) + "\" on all " + inputs + ": "
                    + String.join("; and ", explained)
                    + "; for example, " + d.counterexample(), d.mistake().get(0).reread(),
                    String.join(" + ", d.mistake().stream().map(Variant::title).toList()));
        }
        StringBuilder fact = new StringBuilder("your " + b.method() + " differs from ours on " + d.differing().size()
                + " of " + inputs + "; the simplest: " + d.counterexample());
        d.properties().forEach(p -> fact.append("; ").append(p));
        fact.append("; tick1 does not recognise this mistake");
        return new Finding(b.method(), fact.toString(), sphere ? INTERSECTION_SECTION : ILLUMINATE_SECTION,
                b.method() + ": differs from ours");
    }

    /** The comparison itself, for any report that wants the answers' verdicts. */
    public Behaviour behaviour() {
        return behaviour;
    }

    /** Whether the probes ran (the child logged answers). */
    public boolean ran() {
        return behaviour.ran();
    }

    /** Whether a method does not behave as ours on a tested input. */
    public boolean anyFailed() {
        return !tested.isEmpty();
    }

    /** The tested findings, intersectionWith's first. */
    List<Finding> tested() {
        return tested;
    }

    /** The cohort chart's label of the first tested finding. */
    public String label() {
        return tested.get(0).label();
    }

    /** The notes on what the course's scenes cannot show, each with the label. */
    public List<String> untested() {
        return behaviour.ran() ? behaviour.intersectionWith().untested() : List.of();
    }

    /** The tested findings' facts, one a line. */
    public List<String> facts() {
        return tested.stream().map(Finding::fact).toList();
    }

    /** "behaviour: ..." lines for a failure's explanation, then the untested notes, then "reread: ..." lines. */
    public List<String> failureLines() {
        List<String> lines = new ArrayList<>();
        tested.forEach(f -> lines.add("behaviour: " + f.fact()));
        untested().forEach(note -> lines.add("note: " + note));
        toReread().forEach(section -> lines.add("reread: " + section));
        return lines;
    }

    /** Why the probes did not run, when they did not ({@link #ran}). */
    public String whyNotRan() {
        return noThread ? NO_THREAD : "your methods gave no answer";
    }

    /** What the comparison did find when no method differs. */
    public String noFinding() {
        return behaviour.ran() ? "your intersectionWith and illuminate behave as ours on "
                + Counted.of(behaviour.intersectionWith().inputs() + behaviour.illuminate().inputs(),
                        "input")
                : "your intersectionWith and illuminate could not be checked: "
                        + (noThread ? NO_THREAD : "the harness logged no answer");
    }


    /** The sections to reread as a failure's explanation names them: "handout section 4, ...". */
    public List<String> toReread() {
        return sections().stream().map(Variant::where).toList();
    }

    /**
     * The notes of a pass: each tested finding, which tick1.xml and the hidden scene do not show,
     * then the untested notes.
     */
    public List<String> notes() {
        List<String> notes = new ArrayList<>();
        tested.forEach(f -> notes.add(f.fact() + " (tick1.xml and the hidden scene do not show this; "
                + Variant.where(f.section()) + ")"));
        notes.addAll(untested());
        return notes;
    }

    /** The tested findings' sections, each once, at most {@link #SECTIONS}. */
    List<String> sections() {
        Set<String> sections = new LinkedHashSet<>();
        tested.forEach(f -> sections.add(f.section()));
        return sections.stream().limit(SECTIONS).toList();
    }

    /** The tested facts for a row, a sentence each: a limit on the row cuts between findings, never inside one. */
    public String sentence() {
        return String.join(" ", facts().stream().map(fact -> capitalised(fact) + ".").toList());
    }

    public static String capitalised(String text) {
        return text.isEmpty() ? text : Character.toUpperCase(text.charAt(0)) + text.substring(1);
    }
}
