package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.behaviour.BehaviourFindings;
import gfx.tick1.command.shared.behaviour.PixelCounterexample;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.diagnosis.Diagnoser;
import gfx.tick1.command.shared.diagnosis.Diagnosis;
import gfx.tick1.command.shared.grader.grading.Grading.CourseScene;
import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.model.Findings;
import gfx.tick1.command.shared.grader.model.StudentResult.SceneResult;
import gfx.tick1.command.shared.grader.sandbox.NoImage;
import gfx.tick1.command.shared.grader.sandbox.SceneBatch;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.scene.Intersection;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;

/**
 * The grade's judging step, scene by scene: compares a student image with the references
 * --reference allows, and, when it matches, with what their own methods give for the sampled
 * pixels; explains a difference, and, for a scene that is not hidden, has its images written.
 * A scene that gave no image is judged by why it gave none.
 */
final class SceneJudge {

    /**
     * One scene judged: its result, its verdict, whether its explanation now holds the behaviour
     * comparison's findings, whether its images could not be written, and what its explanation found.
     */
    record Judged(SceneResult result, SceneVerdict verdict, boolean showedProbes, boolean imagesUnwritable,
            Findings found) {

        /** A scene whose explanation found nothing to tally. */
        Judged(SceneResult result, SceneVerdict verdict, boolean showedProbes, boolean imagesUnwritable) {
            this(result, verdict, showedProbes, imagesUnwritable, Findings.NONE);
        }
    }

    /**
     * The figures, diagnosis and findings of a wrong image: its verdict, whether the findings are in
     * it, and what it found.
     */
    private record Explained(SceneVerdict.WrongPixels verdict, boolean showedProbes, Findings found) {
    }

    /** The two references --reference allows for one scene (either may be null: not compared with). */
    private record References(BufferedImage handout, BufferedImage robust) {
        boolean both() {
            return handout != null && robust != null;
        }

        boolean differ() {
            return both() && !Pixels.same(handout, robust);
        }
    }

    /**
     * The student's code, called on a wrong image's differing pixels once {@code hidden} has ended: its answers are
     * quoted in the report, so it never runs beside a hidden scene.
     */
    record Code(PixelCounterexample.Code methods, HiddenRun hidden) {
    }

    private final Grading grading;
    private final BehaviourFindings probes;
    /** The student's code, to call on a wrong image's differing pixels; null: not called. */
    private final Code code;
    private final FeedbackImages images;
    private final PrintWriter out;
    /** Whether a scene judged before the one being judged now has the behaviour comparison's findings. */
    private boolean probesShown;

    /**
     * Judges with the behaviour comparison's {@code probes}, writing images with {@code images};
     * the methods of {@code code} are called on a wrong image's differing pixels when no input
     * showed a difference ({@code code} null: never).
     */
    SceneJudge(Grading grading, BehaviourFindings probes, Code code, FeedbackImages images, PrintWriter out) {
        this.grading = grading;
        this.probes = probes;
        this.code = code;
        this.images = images;
        this.out = out;
    }

    /**
     * The scenes of one batch judged, in grading order (the public ones come first, then the
     * hidden ones), after the {@code earlier} batch's.
     */
    List<Judged> judgeBatch(SceneBatch kind, SceneRuns.Ran ran, List<Judged> earlier) {
        List<CourseScene> batch = grading.batch(kind);
        probesShown = earlier.stream().anyMatch(Judged::showedProbes);
        List<Judged> judged = new ArrayList<>();
        for (int i = 0; i < batch.size(); i++) {
            Judged scene = judge(earlier.size() + i + 1, batch.get(i), ran.outcomes().get(i), ran.traces().get(i));
            probesShown |= scene.showedProbes();
            judged.add(scene);
        }
        return judged;
    }

    /** Scene {@code number} judged. */
    private Judged judge(int number, CourseScene scene, Outcome outcome, String trace) {
        if (outcome instanceof Outcome.Failed failed) {
            return notRendered(scene, failed);
        }
        BufferedImage image = ((Outcome.Rendered) outcome).image();
        ReferenceChoice choice = grading.limits().referenceChoice();
        References references = new References(
                choice == ReferenceChoice.robust ? null : grading.reference(scene, Intersection.HANDOUT),
                choice == ReferenceChoice.handout ? null : grading.reference(scene, Intersection.ROBUST));
        boolean handoutMatched = references.handout() != null && Pixels.same(references.handout(), image);
        if (handoutMatched || references.robust() != null && Pixels.same(references.robust(), image)) {
            SampleCheck.Result check = SampleCheck.check(image, trace);
            return check == SampleCheck.Result.AGREES ? passed(scene, image, references, handoutMatched)
                    : notFromTheCode(scene, check);
        }
        if (scene.hidden()) {
            return wrongHiddenImage(scene);
        }
        return wrongImage(number, scene, image, references);
    }

    /** A scene the code gave no image for: why; for a hidden scene, a {@link HiddenVerdict}'s fixed words. */
    private Judged notRendered(CourseScene scene, Outcome.Failed failed) {
        HiddenVerdict hidden = HiddenVerdict.ofNoImage(failed);
        String reason = scene.hidden() ? hidden.words() : failed.reason();
        out.println(scene.name() + ": FAIL: " + reason.replace("\n", "\n    "));
        // A hidden scene's category is its verdict's: the process total, not the failure beside it.
        NoImage why = scene.hidden() && hidden == HiddenVerdict.PROCESSES ? NoImage.PROCESS_LIMIT : failed.why();
        return new Judged(new SceneResult(scene.name(), scene.hidden(), false, reason.lines().toList(),
                SceneResult.Images.NONE), new SceneVerdict.Missing(why), false, false);
    }

    private Judged passed(CourseScene scene, BufferedImage image, References references, boolean handoutMatched) {
        if (scene.hidden()) {
            // Which reference it matched is the code's to choose, on a scene where the two differ.
            out.println(scene.name() + ": " + HiddenVerdict.PASS.words());
        } else {
            String which = "the reference", other = "";
            if (references.differ()) {
                which = handoutMatched ? "the handout-arithmetic reference" : "the robust reference";
                other = "; the " + (handoutMatched ? "robust" : "handout-arithmetic")
                        + " reference differs on this scene";
            }
            out.println(scene.name() + ": PASS (identical to " + which + ", "
                    + image.getWidth() * image.getHeight() + " pixels" + other + ")");
        }
        return new Judged(new SceneResult(scene.name(), scene.hidden(), true, List.of(), SceneResult.Images.NONE),
                new SceneVerdict.Passed(), false, false);
    }

    /**
     * Why a matching image fails: their own methods give other colours, or could not be asked (in time, or at all,
     * the run's threads being at the limit of processes and threads).
     */
    private Judged notFromTheCode(CourseScene scene, SampleCheck.Result check) {
        String reason = switch (check) {
            case DISAGREES -> Explainer.NOT_FROM_THE_CODE + ": traced through your own intersectionWith and "
                    + "illuminate, its sampled pixels have other colours";
            case NO_THREAD -> "the image could not be checked against your Sphere and Renderer: the program reached "
                    + "the limit of processes and threads (threads the code starts and leaves running count), so no "
                    + "thread could be started to trace its sampled pixels through your intersectionWith and "
                    + "illuminate";
            case NO_TRACE, AGREES -> Explainer.NOT_FROM_THE_CODE + "? Its sampled pixels could not be traced through "
                    + "your intersectionWith and illuminate (they did not return in time, or the harness's record of "
                    + "them is missing)";
        };
        String shown = scene.hidden() ? HiddenVerdict.ofUnconfirmedImage(check).words() : reason;
        out.println(scene.name() + ": FAIL: " + shown);
        // An image no thread was left to check is counted where the run's limit of processes and threads is: nothing
        // was found of where it came from.
        SceneVerdict verdict = check == SampleCheck.Result.NO_THREAD ? new SceneVerdict.Missing(NoImage.PROCESS_LIMIT)
                : new SceneVerdict.NotFromTheCode();
        return new Judged(new SceneResult(scene.name(), scene.hidden(), false, List.of(shown), SceneResult.Images.NONE),
                verdict, false, false);
    }

    /**
     * A hidden scene's wrong image: the fixed verdict, and no figure, diagnosis or image of it
     * (each is the code's to choose). The behaviour comparison's findings and notes follow, if no
     * earlier scene showed them: its inputs are fixed and ran in the run of the public scenes, which
     * never had a hidden one, so they carry nothing of it. The chart's category is the first tested
     * finding's, or that the mistake is not recognised.
     */
    private Judged wrongHiddenImage(CourseScene scene) {
        List<String> lines = new ArrayList<>(List.of(HiddenVerdict.WRONG.words()));
        boolean shows = !probesShown && (probes.anyFailed() || !probes.untested().isEmpty());
        if (shows) {
            lines.addAll(probes.failureLines());
        }
        print(scene, lines);
        return new Judged(new SceneResult(scene.name(), true, false, lines, SceneResult.Images.NONE),
                new SceneVerdict.WrongPixels(probes.anyFailed() ? new Category.Mistake(probes.label())
                        : Category.Outcome.UNRECOGNISED, null),
                shows, false, shows ? found(probes) : Findings.NONE);
    }

    /** A wrong image of a scene that is not hidden: explained against the closer reference, its images written. */
    private Judged wrongImage(int number, CourseScene scene, BufferedImage image, References references) {
        ImageDifference toHandout = references.handout() == null ? null
                : ImageDifference.between(references.handout(), image);
        ImageDifference toRobust = references.robust() == null ? null
                : ImageDifference.between(references.robust(), image);
        boolean againstHandout = toRobust == null
                || toHandout != null && toHandout.differingPixels() < toRobust.differingPixels();
        ImageDifference difference = againstHandout ? toHandout : toRobust;
        List<String> lines = new ArrayList<>();
        lines.add(difference.summary());
        if (references.differ()) {
            lines.add("(compared with the " + (againstHandout ? "handout-arithmetic" : "robust")
                    + " reference, the closer of the two, which differ on this scene)");
        }
        Explained explained = explain(scene, image, againstHandout ? references.handout() : references.robust(),
                difference, lines);
        print(scene, lines);
        Optional<SceneResult.Images> written = images.write(number, scene, image, difference,
                againstHandout ? references.handout() : references.robust());
        SceneResult result = new SceneResult(scene.name(), false, false, lines,
                written.orElse(SceneResult.Images.NONE));
        Findings found = explained.found();
        return new Judged(result, explained.verdict(), explained.showedProbes(), written.isEmpty(),
                new Findings(found.catalogued(), found.failed(), found.notes(),
                        found.figures().stream().map(figures -> "scene " + number + ": " + figures).toList(),
                        found.reread()));
    }

    /**
     * The figures and the diagnosis of a wrong image, then the failed probes (the first wrong image
     * only) and what to reread, added to {@code lines}; its verdict.
     */
    private Explained explain(CourseScene scene, BufferedImage image, BufferedImage reference,
            ImageDifference difference, List<String> lines) {
        double[] mean = difference.meanPerChannel();
        String figures = String.format("mean difference R %.3f, G %.3f, B %.3f levels; PSNR %.2f dB", mean[0],
                mean[1], mean[2], difference.psnr());
        lines.add(figures);
        // An entry whose model answers otherwise than their methods is neither a cause nor a candidate,
        // and is not rendered.
        Set<Variant> ruledOut = EnumSet.noneOf(Variant.class);
        Stream.of(Variant.values()).filter(v -> !probes.behaviour().allows(v)).forEach(ruledOut::add);
        Set<Variant> considered = EnumSet.allOf(Variant.class);
        considered.removeAll(ruledOut);
        Diagnosis diagnosis = new Diagnoser().diagnose(image, scene.scene(), null, considered);
        List<Variant> matching = diagnosis.verdict() != Diagnosis.Verdict.EXPLAINED ? List.of()
                : diagnosis.explaining().stream().map(Diagnosis.Candidate::variant).filter(v -> !ruledOut.contains(v))
                .toList();
        boolean exact = !matching.isEmpty();
        boolean behaviourSays = probes.anyFailed();
        // What to reread comes from the tested findings; the image's own entry only when it matches exactly.
        boolean imageSaysReread = exact && !behaviourSays;
        // No candidate of an unsure image is one the answers leave possible only as part of it.
        Set<Variant> notCandidates = EnumSet.noneOf(Variant.class);
        notCandidates.addAll(ruledOut);
        if (diagnosis.verdict() == Diagnosis.Verdict.UNSURE) {
            Stream.of(Variant.values()).filter(v -> !probes.behaviour().allowsAlone(v)).forEach(notCandidates::add);
        }
        // The code rendered the scene it was given: its image shows no other scene.
        lines.addAll(diagnosis.report(imageSaysReread, notCandidates, true));
        List<String> reread = new ArrayList<>(imageSaysReread ? diagnosis.toReread().stream().toList() : List.of());
        boolean shows = !probesShown && (behaviourSays || !probes.untested().isEmpty());
        Findings found = shows ? found(probes) : Findings.NONE;
        // No input showed a difference, yet the image differs: its own pixels' rays are asked.
        PixelCounterexample.Found pixel = !behaviourSays && !exact && probes.ran() && code != null
                ? pixelCounterexample(scene, reference, image) : null;
        if (pixel != null && pixel.differs()) {
            lines.add("behaviour: " + pixel.words());
        }
        if (shows) {
            lines.addAll(probes.failureLines());
        }
        if (pixel != null && pixel.differs()) {
            found = new Findings(null, List.of(pixel.words()), found.notes(), List.of(), found.reread());
        } else if (!shows && !behaviourSays && !exact) {
            String fact = probes.noFinding() + (pixel == null ? "" : "; " + pixel.words());
            lines.add("behaviour: " + fact);
            found = new Findings(null, List.of(fact), List.of(), List.of(), List.of());
        }
        reread.addAll(found.reread());
        Variant catalogued = exact ? matching.get(0) : null;
        String title = exact ? catalogued.title() : null;
        String exactly = exact ? (scene.hidden() ? "A hidden scene" : scene.name()) + " is exactly the image of \""
                + title + "\"." : null;
        // The chart counts exact matches first, then tested findings; never what the scenes cannot show.
        Category category = exact ? new Category.Mistake(title) : behaviourSays ? new Category.Mistake(probes.label())
                : Category.Outcome.UNRECOGNISED;
        return new Explained(new SceneVerdict.WrongPixels(category, exactly,
                pixel != null && pixel.differs() ? pixel.words() : null), shows,
                new Findings(catalogued, found.failed(), found.notes(), List.of(figures), reread));
    }

    /** Their methods called on the differing pixels of {@code image}; null when they could not be. */
    private PixelCounterexample.Found pixelCounterexample(CourseScene scene, BufferedImage reference,
            BufferedImage image) {
        try {
            code.hidden().awaitEnd();
            return PixelCounterexample.find(code.methods(), scene.scene(), scene.name(), reference, image);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt(); // the grade is being stopped: the caller's next wait ends it
            return null;
        }
    }

    /** What {@link BehaviourFindings#failureLines} words: the tested facts, the untested notes, what to reread. */
    private static Findings found(BehaviourFindings behaviour) {
        return new Findings(null, behaviour.facts(), behaviour.untested(), List.of(), behaviour.toReread());
    }

    private void print(CourseScene scene, List<String> lines) {
        out.println(scene.name() + ": FAIL: " + lines.get(0));
        lines.subList(1, lines.size()).forEach(line -> out.println("  " + line));
    }
}
