package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.grader.harness.BehaviourInputs;
import gfx.tick1.command.shared.grader.sandbox.Leftovers;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.SceneBatch;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import gfx.tick1.engine.io.Counted;
import gfx.tick1.engine.io.OnExit;
import gfx.tick1.engine.render.GoldenImages;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The behaviour of a Sphere.java and a Renderer.java on their own, for {@code tick1 diff}: compiled
 * with the starter kit and run in the sandbox, as {@code grade} runs them, with no scene, on the
 * behaviour's inputs. For each method asked about, one line: that it behaves as ours, or the finding
 * ({@link BehaviourFindings}) and the notes on mistakes the course's scenes cannot show; then the
 * hints of what to reread. Where the methods cannot run (no sandbox, the files do not compile), there
 * is nothing but one line that says why.
 */
public final class BehaviourCheck {

    /**
     * What the methods asked about did: one line each, each followed by its "note: ..." lines,
     * first; then "hint: ..." lines; or, when they could not be run, none and why. {@code drawn}: the
     * handout's scenes as the code drew them, when asked for and the code ran; else null.
     */
    public record Lines(List<String> behaviour, List<String> hints, String whyNone, boolean behavesAsOurs,
            DrawnScenes drawn) {

        static Lines none(String why) {
            return new Lines(List.of(), List.of(), why, false, null);
        }
    }

    /** The words of a method's line when it behaves as ours. */
    static final String BEHAVES_AS_OURS = " behaves as ours on ";

    private static final Duration TIME_LIMIT = Duration.ofSeconds(30);
    private static final int MEMORY_MEGABYTES = 512;

    /** The limits of the methods' JVM that hold without the sandbox too, in words. */
    public static final String LIMITS = "a Java process of their own limited only in time (" + TIME_LIMIT.toSeconds()
            + " s to compile, as long again to run) and heap (" + MEMORY_MEGABYTES + " MiB)";

    private BehaviourCheck() {
    }

    /**
     * Calls the methods of {@code sphere} and {@code renderer} (sources of package gfx.tick1),
     * run in the sandbox {@code where} makes; hints only of the methods of the files named in
     * {@code asked} ("Sphere", "Renderer"). With {@code draw}, the same run also draws
     * {@link DrawnScenes#SCENES}, and ours are drawn meanwhile.
     */
    public static Lines check(String sphere, String renderer, List<String> asked, SandboxAhead where, boolean draw)
            throws InterruptedException {
        Sandbox sandbox;
        try {
            sandbox = where.sandbox();
        } catch (Sandbox.Unavailable e) {
            return Lines.none("behaviour could not be checked: it comes from running your methods in "
                    + "the sandbox, and " + e.getMessage() + (e.remedy() == null ? "" : ": " + e.remedy())
                    + "; if the code is yours, --no-sandbox runs them without one");
        }
        CompletableFuture<List<BufferedImage>> ours = draw ? DrawnScenes.drawOurs() : null;
        Called called = call(sandbox, sphere, renderer, null, draw);
        if (called.log() == null) {
            return Lines.none(called.whyNone());
        }
        BehaviourFindings findings = BehaviourFindings.of(called.log());
        if (!findings.ran()) {
            return Lines.none("behaviour could not be checked: " + findings.whyNotRan());
        }
        Lines lines = hints(findings, asked);
        return called.drawn() == null ? lines : new Lines(lines.behaviour(), lines.hints(), null,
                lines.behavesAsOurs(), DrawnScenes.of(called.drawn(), ours.join()));
    }

    /**
     * The harness's log of the methods' answers, or (log null) why there is none, in words; and what
     * became of the scenes drawn, or null.
     */
    record Called(String log, String whyNone, List<StudentProcess.Outcome> drawn) {
        Called(String log, String whyNone) {
            this(log, whyNone, null);
        }
    }

    /**
     * Compiles {@code sphere} and {@code renderer} with the starter kit in {@code sandbox} and calls
     * their methods on the fixed inputs, or, when {@code chosen} is not null, on those alone.
     */
    static Called call(Sandbox sandbox, String sphere, String renderer, BehaviourInputs.Chosen chosen)
            throws InterruptedException {
        return call(sandbox, sphere, renderer, chosen, false);
    }

    /** As above; with {@code draw}, the run also draws {@link DrawnScenes#SCENES} at the handout's size. */
    private static Called call(Sandbox sandbox, String sphere, String renderer, BehaviourInputs.Chosen chosen,
            boolean draw) throws InterruptedException {
        OnExit deleted = null;
        try {
            Path work = Leftovers.newWorkFolder("behaviour");
            // However tick1 ends (Ctrl-C, SIGTERM while the methods run), the folder and the run's tmpfs go.
            deleted = OnExit.run("tick1-behaviour-clean-up", () -> WorkFolder.delete(work));
            return call(sandbox, work, sphere, renderer, chosen, draw);
        } catch (IOException e) {
            return new Called(null, "behaviour could not be checked: your methods could not be run ("
                    + e.getMessage() + ")");
        } finally {
            if (deleted != null) {
                deleted.now();
            }
        }
    }

    private static Called call(Sandbox sandbox, Path work, String sphere, String renderer,
            BehaviourInputs.Chosen chosen, boolean draw) throws IOException, InterruptedException {
        Path harness = Files.createDirectory(work.resolve("harness"));
        StudentProcess.writeHarness(harness);
        if (chosen != null) {
            Files.writeString(harness.resolve(BehaviourInputs.CHOSEN_FILE), chosen.text(), StandardCharsets.UTF_8);
        }
        StudentProcess process = new StudentProcess(sandbox, harness, MEMORY_MEGABYTES);
        Path sources = StudentProcess.writeSources(work, sphere, renderer);
        Path scenes = Files.createDirectory(work.resolve("scenes"));
        if (draw) {
            DrawnScenes.write(scenes);
        }
        sandbox.share(work);
        Path output = Files.createDirectory(work.resolve("output"));
        sandbox.shareWritable(output);
        StudentProcess.Batch batch = draw ? new StudentProcess.Batch(scenes, DrawnScenes.SCENES, GoldenImages.WIDTH,
                GoldenImages.HEIGHT, SceneBatch.PUBLIC) : new StudentProcess.Batch(scenes, List.of(), 1, 1,
                SceneBatch.PUBLIC);
        StudentProcess.CompiledAndRendered run = process.compileAndRender(sources, batch, output, "Sphere.java",
                "Renderer.java", TIME_LIMIT);
        if (!run.compiled().compiled()) {
            return new Called(null, "behaviour could not be checked: it comes from running your "
                    + "methods, and the files do not compile with the starter code"
                    + (run.compiled().failure() == null ? ""
                    : " (" + run.compiled().failure() + ")"));
        }
        return new Called(run.rendered().probes(), null, draw ? run.rendered().outcomes() : null);
    }

    /** The lines of the methods of the files named in {@code asked}. */
    static Lines hints(BehaviourFindings findings, List<String> asked) {
        List<String> behaviour = new ArrayList<>(), hints = new ArrayList<>();
        boolean ours = true;
        Behaviour b = findings.behaviour();
        for (MethodBehaviour method : List.of(b.intersectionWith(), b.illuminate())) {
            if (!asked.contains(method.method().equals("intersectionWith") ? "Sphere" : "Renderer")) {
                continue;
            }
            if (method.behavesAsOurs()) {
                behaviour.add("your " + method.method() + BEHAVES_AS_OURS + Counted.of(method.inputs(),
                        "input"));
            } else {
                ours = false;
                BehaviourFindings.Finding finding = findings.tested().stream()
                        .filter(f -> f.method().equals(method.method())).findFirst().orElseThrow();
                behaviour.add(finding.fact());
                hints.add("hint: reread " + Variant.where(finding.section()) + ".");
            }
            // A mistake only an untested edge shows is still one: told beside its method's line, before the diff.
            method.untested().forEach(note -> behaviour.add("note: " + note));
            ours &= method.untested().isEmpty();
        }
        return new Lines(behaviour, hints, null, ours, null);
    }
}
