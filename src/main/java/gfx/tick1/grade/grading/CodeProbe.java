package gfx.tick1.grade.grading;

import gfx.tick1.grade.sandbox.Sandbox;
import gfx.tick1.grade.sandbox.StudentProcess;
import gfx.tick1.grade.sandbox.WorkFolder;
import gfx.tick1.starter.StarterKit;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * The probes of a Sphere.java and a Renderer.java on their own, for {@code tick1 diff}: compiled
 * with the starter kit and run in the sandbox, as {@code grade} runs them, with no scene. The
 * hints are the facts of the failed probes of the methods asked about; where the probes cannot
 * run (no sandbox, the files do not compile), there are none, and one line says why.
 */
public final class CodeProbe {

    /** The hints, each "fact: reread handout section.", or none and why. */
    public record Hints(List<String> hints, String whyNone) {
    }

    private static final Duration TIME_LIMIT = Duration.ofSeconds(30);
    private static final int MEMORY_MEGABYTES = 512;

    private CodeProbe() {
    }

    /**
     * Probes {@code sphere} and {@code renderer} (sources of package gfx.tick1); hints only of the
     * methods of the files named in {@code asked} ("Sphere", "Renderer").
     */
    public static Hints probe(String sphere, String renderer, List<String> asked) throws InterruptedException {
        Sandbox sandbox;
        try {
            sandbox = Sandbox.confined();
        } catch (Sandbox.Unavailable e) {
            return new Hints(List.of(), "no hints: they come from running your methods in the sandbox, and "
                    + e.getMessage() + " (install " + Sandbox.PACKAGE + ")");
        }
        Path work = null;
        try {
            work = Files.createTempDirectory("tick1-diff");
            return probe(sandbox, work, sphere, renderer, asked);
        } catch (IOException e) {
            return new Hints(List.of(), "no hints: the probes of your methods could not run (" + e.getMessage() + ")");
        } finally {
            if (work != null) {
                WorkFolder.delete(work);
            }
        }
    }

    private static Hints probe(Sandbox sandbox, Path work, String sphere, String renderer, List<String> asked)
            throws IOException, InterruptedException {
        Path harness = Files.createDirectory(work.resolve("harness"));
        StudentProcess.writeHarness(harness);
        StudentProcess process = new StudentProcess(sandbox, harness, MEMORY_MEGABYTES);
        Path sources = Files.createDirectory(work.resolve("sources"));
        Files.writeString(sources.resolve("Sphere.java"), sphere, StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("Renderer.java"), renderer, StandardCharsets.UTF_8);
        for (String given : StarterKit.GIVEN_CLASSES) {
            Files.writeString(sources.resolve(given + ".java"), StarterKit.source(given), StandardCharsets.UTF_8);
        }
        Path scenes = Files.createDirectory(work.resolve("scenes"));
        sandbox.share(work, false);
        Path output = Files.createDirectory(work.resolve("output"));
        sandbox.share(output, true);
        StudentProcess.CompiledAndRendered run = process.compileAndRender(sources, scenes, List.of(), output,
                "Sphere.java", "Renderer.java", 1, 1, TIME_LIMIT, true);
        if (!run.compiled().compiled()) {
            return new Hints(List.of(), "no hints: they come from running your methods, and the files do not "
                    + "compile with the starter code" + (run.compiled().failure() == null ? ""
                    : " (" + run.compiled().failure() + ")"));
        }
        ProbeFindings findings = ProbeFindings.of(run.rendered().probes());
        if (!findings.ran()) {
            return new Hints(List.of(), "no hints: the probes of your methods did not run to the end");
        }
        List<String> hints = new ArrayList<>();
        List<ProbeJudge.Judgement> failed = findings.failed();
        for (ProbeJudge.Judgement j : failed) {
            boolean mine = j.probe().method().equals("intersectionWith") ? asked.contains("Sphere")
                    : asked.contains("Renderer");
            if (mine) {
                hints.add(j.fact() + ": reread handout " + j.section() + ".");
            }
        }
        return new Hints(hints, null);
    }
}
