package gfx.tick1.command.shared.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;
import java.util.stream.Stream;

/**
 * Why no given scene catches a mistake, where tick1 knows why. A reason is given only when it
 * holds for the scenes given: that no scene has the camera inside a sphere is said only when none
 * has. Every ray of the tick starts at the camera, at the origin, with a unit direction.
 */
public enum KnownReason {

    NAN_IS_NEVER_CLOSEST(EnumSet.of(Variant.UNCHECKED_NEGATIVE_SQUARE_ROOT),
            "no scene can show it: a NaN distance never beats the closest hit, so a missed sphere stays missed",
            scene -> true),
    K_D_IS_K_S(EnumSet.of(Variant.KD_SWAPPED_WITH_KS),
            "no scene can show it: every sphere of the tick has k_d = k_s",
            scene -> scene.getObjects().stream().allMatch(sphere -> sphere.getPhong_kD() == sphere.getPhong_kS())),
    CAMERA_OUTSIDE_EVERY_SPHERE(EnumSet.of(Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT, Variant.DISTANCE_ALWAYS_S1),
            "it shows only where a ray starts inside a sphere, and every ray starts at the origin, which no "
                    + "sphere of these scenes holds; a scene that has one fails the handout's six steps taken "
                    + "literally, a correct answer, as well",
            scene -> scene.getObjects().stream().allMatch(sphere -> atTheCamera(sphere) >= 0)),
    NO_SURFACE_THROUGH_THE_CAMERA(EnumSet.of(Variant.ROOTS_ACCEPTED_AT_ZERO),
            "it shows only where a ray starts on a sphere's surface, and every ray starts at the origin, which no "
                    + "sphere's surface of these scenes passes through",
            scene -> scene.getObjects().stream().allMatch(sphere -> atTheCamera(sphere) != 0)),
    UNIT_DIRECTIONS(EnumSet.of(Variant.DIVIDED_BY_2_TIMES_A),
            "every ray's direction is a unit vector, so a = D.D is 1 but for its last bit and a root moves in its "
                    + "last bit only, as in correct code that computes in another order: a scene made to show it "
                    + "would be as sensitive to such code",
            scene -> true);

    private final Set<Variant> entries;
    private final String words;
    private final Predicate<Scene> holds;

    KnownReason(Set<Variant> entries, String words, Predicate<Scene> holds) {
        this.entries = entries;
        this.words = words;
        this.holds = holds;
    }

    /** The reason, in words without a capital or a full stop. */
    public String words() {
        return words;
    }

    /**
     * Whether no scene of the tick can show the mistake, whatever its spheres and lights, without
     * failing an answer as correct as ours: the handout's six steps taken literally, or correct code
     * that computes in another order.
     */
    public boolean noFairSceneCan() {
        return this != NO_SURFACE_THROUGH_THE_CAMERA;
    }

    /** The mistakes that no fair scene can show, as {@link #noFairSceneCan()} says. */
    public static Set<Variant> shownByNoFairScene() {
        Set<Variant> none = EnumSet.noneOf(Variant.class);
        Stream.of(values()).filter(KnownReason::noFairSceneCan).forEach(reason -> none.addAll(reason.entries));
        return none;
    }

    /** The reason tick1 knows why none of {@code scenes} catches {@code mistake}, if it knows one. */
    public static Optional<KnownReason> of(Variant mistake, List<Scene> scenes) {
        for (KnownReason reason : values()) {
            if (reason.entries.contains(mistake) && scenes.stream().allMatch(reason.holds)) {
                return Optional.of(reason);
            }
        }
        return Optional.empty();
    }

    /**
     * c = |O - C|^2 - r^2 for a ray from the camera, as intersectionWith computes it: negative
     * when the camera is inside the sphere, 0 when it is on the surface.
     */
    private static double atTheCamera(Sphere sphere) {
        Vector3 toCamera = new Vector3(0).subtract(SphereGeometry.centre(sphere));
        return toCamera.dot(toCamera) - Math.pow(SphereGeometry.radius(sphere), 2);
    }
}
