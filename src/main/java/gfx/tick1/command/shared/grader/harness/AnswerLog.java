package gfx.tick1.command.shared.grader.harness;

import gfx.tick1.command.shared.grader.harness.BehaviourInputs.Phong;
import java.io.IOException;
import java.io.OutputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Calls the student's {@code intersectionWith} and {@code illuminate} on each of {@link BehaviourInputs}
 * and logs what each returned, one line a call, as soon as it returns: a run stopped on the time
 * limit keeps the lines before. The lines are raw numbers; the grader, which trusts nothing this
 * process writes, parses them and decides. A call that throws is logged as {@code threw}, one that
 * does not return within {@link #CALL_MILLIS} ({@link Bounded}: of its own processor time) as {@code timeout}, and
 * the next call goes on. The
 * random inputs of each method are called in one batch, with {@link #BATCH_MILLIS} for the lot: a
 * call that does not return leaves the rest of its batch unanswered. Before the random shadings,
 * one line says whether their k_d, k_s and n could be set through the starter Sphere's fields
 * ({@code phong set}), or whether every sphere keeps the course's ({@code phong fixed}).
 *
 * <pre>
 * NAME hit SAME DISTANCE PX PY PZ NX NY NZ   (SAME: 1 when the hit names the sphere called)
 * NAME none                                  (an empty RaycastHit: no sphere)
 * NAME colour R G B
 * NAME null | threw | timeout | absent       (absent: no illuminate(Scene, Sphere, Vector3, Vector3))
 * phong set | phong fixed
 * nothread                                   (the next call found no thread to run in: the last line)
 * </pre>
 */
public final class AnswerLog {

    static final String ANSWERS_FILE = "probes";
    /** The line that ends a log whose next call found no thread to run in: the calls left were never made. */
    public static final String NO_THREAD = "nothread";
    /** The most one call may take: an answer is one sphere and one point. */
    static final long CALL_MILLIS = 500;
    /** The most one method's random inputs may take together: a correct method takes milliseconds. */
    static final long BATCH_MILLIS = 5000;

    private final StarterApi api;

    AnswerLog(StarterApi api) {
        this.api = api;
    }

    /**
     * Calls the methods of the compiled classes {@code student} can load, logging into {@code log};
     * nothing when they lack the starter's API.
     */
    public static void write(ClassLoader student, Path log) throws IOException {
        StarterApi api;
        try {
            api = new StarterApi(student);
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            return; // no Sphere.intersectionWith(Ray) to call: every input fails for want of an answer
        }
        new AnswerLog(api).run(log);
    }

    void run(Path log) throws IOException {
        try (OutputStream out = Files.newOutputStream(log, StandardOpenOption.CREATE, StandardOpenOption.APPEND)) {
            Lines lines = new Lines(out);
            try {
                answerAll(lines);
            } catch (NoThread atTheLimit) {
                // The calls left would find no thread either: they get no line, and the log says why.
                lines.write(NO_THREAD);
            }
        }
    }

    private void answerAll(Lines lines) {
        BehaviourInputs.Chosen chosen = chosen();
        if (chosen != null) {
            batch(lines, chosen.intersections(), call -> intersect(call));
            if (api.hasIlluminate()) {
                batch(lines, chosen.illuminations(), call -> illuminate(call, Phong.FIXED));
            }
            return;
        }
        for (BehaviourInputs.IntersectionCall call : BehaviourInputs.INTERSECTIONS) {
            lines.write(call.name(), Bounded.RUN.call(() -> intersect(call), CALL_MILLIS));
        }
        for (BehaviourInputs.IlluminationCall call : BehaviourInputs.ILLUMINATIONS) {
            lines.write(call.name(), api.hasIlluminate()
                    ? Bounded.RUN.call(() -> illuminate(call, Phong.FIXED), CALL_MILLIS)
                    : new Bounded.Outcome<>(Bounded.Ending.RETURNED, "absent"));
        }
        batch(lines, BehaviourInputs.RANDOM_INTERSECTIONS, call -> intersect(call));
        Phong phong = api.hasPhongFields() ? Phong.SET : Phong.FIXED;
        lines.write("phong", new Bounded.Outcome<>(Bounded.Ending.RETURNED, phong.word()));
        if (api.hasIlluminate()) {
            batch(lines, BehaviourInputs.RANDOM_ILLUMINATIONS, call -> illuminate(call, phong));
        } else {
            for (BehaviourInputs.IlluminationCall call : BehaviourInputs.RANDOM_ILLUMINATIONS) {
                lines.write(call.name(), new Bounded.Outcome<>(Bounded.Ending.RETURNED, "absent"));
            }
        }
    }

    /** The inputs the grader chose, from the file beside the harness's jar; null when there is none. */
    private static BehaviourInputs.Chosen chosen() {
        try {
            Path jar = Path.of(AnswerLog.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            Path file = jar.resolveSibling(BehaviourInputs.CHOSEN_FILE);
            return Files.isRegularFile(file) ? BehaviourInputs.Chosen.read(Files.readString(file,
                    StandardCharsets.UTF_8)) : null;
        } catch (URISyntaxException | IOException | RuntimeException e) {
            return null;
        }
    }

    /** One call of the student's method, as the line's answer. */
    private interface Call<T> {
        String answer(T call) throws ReflectiveOperationException;
    }

    /**
     * Calls {@code answer} on each of {@code calls} in one thread, with {@link #BATCH_MILLIS} for
     * all of them; each answer is logged as it comes. Once the time is up, nothing more of the
     * batch is logged, even if the call that did not return comes back later.
     */
    private static <T extends Record> void batch(Lines lines, List<T> calls, Call<T> answer) {
        AtomicBoolean open = new AtomicBoolean(true);
        Bounded.Outcome<Object> outcome = Bounded.RUN.call(() -> {
            for (T call : calls) {
                String said;
                try {
                    said = answer.answer(call);
                } catch (ReflectiveOperationException | RuntimeException | LinkageError | StackOverflowError e) {
                    said = "threw";
                }
                synchronized (lines) {
                    if (!open.get()) {
                        return null;
                    }
                    lines.write(name(call), new Bounded.Outcome<>(Bounded.Ending.RETURNED, said));
                }
            }
            return null;
        }, BATCH_MILLIS);
        synchronized (lines) {
            open.set(false);
        }
        if (outcome.ending() == Bounded.Ending.NO_THREAD) {
            throw new NoThread();
        }
    }

    private static String name(Record call) {
        return call instanceof BehaviourInputs.IntersectionCall i ? i.name()
                : ((BehaviourInputs.IlluminationCall) call).name();
    }

    private String intersect(BehaviourInputs.IntersectionCall call) throws ReflectiveOperationException {
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

    private String illuminate(BehaviourInputs.IlluminationCall call, Phong phong)
            throws ReflectiveOperationException {
        BehaviourInputs.LightInput light = call.light();
        BehaviourInputs.Material material = call.sphere().material();
        Object scene = api.scene(call.ambient(), light.position(), light.colour(), light.intensity());
        Object sphere = api.sphere(call.sphere().centre(), call.sphere().radius(), material.colour());
        if (phong == Phong.SET) {
            api.setPhong(sphere, material.kD(), material.kS(), material.n());
        }
        Object colour = api.illuminate(api.renderer(1, 1), scene, sphere, api.vector(call.point()),
                api.vector(call.normal()));
        if (colour == null) {
            return "null";
        }
        double[] rgb = api.components(colour);
        return "colour " + rgb[0] + " " + rgb[1] + " " + rgb[2];
    }

    /** The log, one line a call, each written whole as soon as it is known. */
    private static final class Lines {
        private final OutputStream out;

        Lines(OutputStream out) {
            this.out = out;
        }

        /** Writes "NAME ANSWER"; a write that fails is left out. */
        void write(String name, Bounded.Outcome<String> outcome) {
            String said = switch (outcome.ending()) {
                case RETURNED -> outcome.value();
                case THREW -> "threw";
                case TIMED_OUT -> "timeout";
                case NO_THREAD -> throw new NoThread();
            };
            write(name + " " + said);
        }

        /** Writes {@code line}; a write that fails is left out. */
        void write(String line) {
            try {
                out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
            } catch (IOException e) {
                // the student's code may have closed or filled the log: its answers are then missing
            }
        }
    }

    /** A call's thread could not be started: the run's threads are at the limit of processes and threads. */
    private static final class NoThread extends RuntimeException {
        private static final long serialVersionUID = 1L;
    }
}
