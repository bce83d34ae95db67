package gfx.tick1.grade.harness;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * Calls the student's {@code intersectionWith} and {@code illuminate} on each of {@link ProbeCalls}
 * and logs what each returned, one line a call, as soon as it returns: a run stopped on the time
 * limit keeps the lines before. The lines are raw numbers; the grader, which trusts nothing this
 * process writes, parses them and decides. A call that throws is logged as {@code threw}, one that
 * does not return within {@link #CALL_MILLIS} as {@code timeout}, and the next call goes on.
 *
 * <pre>
 * NAME hit SAME DISTANCE PX PY PZ NX NY NZ   (SAME: 1 when the hit names the sphere called)
 * NAME none                                  (an empty RaycastHit: no sphere)
 * NAME colour R G B
 * NAME null | threw | timeout | absent       (absent: no illuminate(Scene, Sphere, Vector3, Vector3))
 * </pre>
 */
public final class ProbeRunner {

    static final String PROBES_FILE = "probes";
    /** The most one call may take: a probe's answer is one sphere and one point. */
    static final long CALL_MILLIS = 500;

    private final StarterApi api;

    ProbeRunner(StarterApi api) {
        this.api = api;
    }

    /**
     * Runs the probes on the compiled classes {@code student} can load, logging into {@code log};
     * nothing when they lack the starter's API.
     */
    public static void probe(ClassLoader student, Path log) throws IOException {
        StarterApi api;
        try {
            api = new StarterApi(student);
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            return; // no Sphere.intersectionWith(Ray) to call: every probe fails for want of an answer
        }
        new ProbeRunner(api).run(log);
    }

    void run(Path log) throws IOException {
        for (ProbeCalls.Intersection call : ProbeCalls.INTERSECTIONS) {
            Bounded.Outcome<String> outcome = Bounded.call(() -> intersect(call), CALL_MILLIS);
            write(log, call.name(), outcome);
        }
        for (ProbeCalls.Illumination call : ProbeCalls.ILLUMINATIONS) {
            if (!api.hasIlluminate()) {
                write(log, call.name(), new Bounded.Outcome<>(Bounded.Ending.RETURNED, "absent"));
                continue;
            }
            Bounded.Outcome<String> outcome = Bounded.call(() -> illuminate(call), CALL_MILLIS);
            write(log, call.name(), outcome);
        }
    }

    private String intersect(ProbeCalls.Intersection call) throws ReflectiveOperationException {
        Object sphere = api.sphere(call.centre(), call.radius(), new double[] {1, 1, 1});
        Object hit = api.intersectionWith(sphere, api.ray(call.origin(), call.direction()));
        if (hit == null) {
            return "null";
        }
        Object object = api.objectHit(hit);
        if (object == null) {
            return "none";
        }
        StringBuilder line = new StringBuilder("hit ").append(object == sphere ? 1 : 0).append(' ')
                .append(api.distance(hit));
        for (double value : api.components(api.location(hit))) {
            line.append(' ').append(value);
        }
        for (double value : api.components(api.normal(hit))) {
            line.append(' ').append(value);
        }
        return line.toString();
    }

    private String illuminate(ProbeCalls.Illumination call) throws ReflectiveOperationException {
        Object scene = api.scene(call.ambient(), call.light(), call.lightColour(), call.intensity());
        Object sphere = api.sphere(call.centre(), call.radius(), call.colour());
        Object colour = api.illuminate(api.renderer(1, 1), scene, sphere, api.vector(call.point()),
                api.vector(call.normal()));
        if (colour == null) {
            return "null";
        }
        double[] rgb = api.components(colour);
        return "colour " + rgb[0] + " " + rgb[1] + " " + rgb[2];
    }

    private static void write(Path log, String name, Bounded.Outcome<String> outcome) throws IOException {
        String said = switch (outcome.ending()) {
            case RETURNED -> outcome.value();
            case THREW -> "threw";
            case TIMED_OUT -> "timeout";
        };
        Files.writeString(log, name + " " + said + "\n", StandardCharsets.UTF_8,
                StandardOpenOption.CREATE, StandardOpenOption.APPEND);
    }
}
