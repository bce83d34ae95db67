package gfx.tick1.grade.grading;

import java.util.List;

/**
 * One property of a student's {@code Sphere.intersectionWith} or {@code Renderer.illuminate},
 * checked by calling it on fixed inputs ({@link gfx.tick1.grade.harness.ProbeCalls}) and comparing
 * with the reference ({@link ProbeReference}); {@link ProbeJudge} decides each. A probe is judged
 * only when the probes it rests on hold, so that one mistake is one failed property, not a cascade:
 * the distance of a hit is not judged when there is no hit, and no term of illuminate is judged
 * when it returns the sphere's colour whatever the light.
 */
enum Probe {

    HIT("intersectionWith", "a ray that meets a sphere in front of it",
            "section 4, \"Ray-sphere intersection code\" (steps 3 to 5, and the RaycastHit to return)", null),
    MISS("intersectionWith", "a ray that misses the sphere",
            "section 4, steps 1 and 2 (a negative discriminant means no intersection)", null),
    POINTS_AWAY("intersectionWith", "a ray that points away from the sphere",
            "section 4, step 6 (neither root positive: no intersection)", null),
    BEHIND("intersectionWith", "a sphere wholly behind the ray's origin",
            "section 4, step 6 (neither root positive: no intersection)", null),
    NEAREST_ROOT("intersectionWith", "a ray that meets a sphere in front of it",
            "section 4, steps 4 and 5 (use the solution closest to the ray origin)", null, HIT),
    POINT("intersectionWith", "a ray that meets a sphere in front of it",
            "section 4, \"Ray-sphere intersection code\" (Vector3 point = ray.evaluateAt(s))", null, HIT),
    NORMAL("intersectionWith", "a ray that meets a sphere in front of it",
            "section 4, \"Ray-sphere intersection code\" (Vector3 normal = this.getNormalAt(point))", null, HIT,
            POINT),
    GRAZE("intersectionWith", "a ray that grazes the sphere",
            "section 4, steps 4 to 6", "the handout's six steps leave it open, and the reference takes the "
                    + "nearest positive root", HIT, NEAREST_ROOT),
    INSIDE("intersectionWith", "a ray that starts inside a sphere",
            "section 4, steps 4 to 6", "the handout's six steps leave it open, and the reference takes the "
                    + "nearest positive root", HIT),
    ON_SURFACE("intersectionWith", "a ray that starts on a sphere's surface",
            "section 4, steps 4 to 6 (a hit is at s > 0)", "the handout asks for s > 0", HIT, NEAREST_ROOT),

    PLACEHOLDER("illuminate", "a point lit by the scene's lights", "section 5, \"Phong illumination code\"", null),
    SCALE("illuminate", "a point lit by the scene's lights",
            "section 2, \"Vector3\" (colours are x, y, z = r, g, b, each from 0 to 1)", null, PLACEHOLDER),
    CHANNELS("illuminate", "a pure red, green or blue surface in white ambient light",
            "section 2, \"Vector3\" (colours are x, y, z = r, g, b)", null, SCALE),
    AMBIENT("illuminate", "a point with the point light off (intensity 0)",
            "section 5, \"The Phong illumination model\" (ambient lighting: C_diff I_a)", null, CHANNELS),
    DIFFUSE("illuminate", "a point with the light along its normal at distance 1",
            "section 5, \"The Phong illumination model\" (diffuse lighting: C_diff k_d I max(0, N.L))", null,
            SCALE),
    FALL_OFF("illuminate", "a point with the light along its normal at distance 2",
            "section 5, \"Diffuse lighting\" (I decreases over distance: intensity / (4 pi d^2))", null, DIFFUSE),
    SPECULAR("illuminate", "a point with the light along its normal",
            "section 5, \"The Phong illumination model\" (specular lighting)", null, SCALE),
    CAMERA_DIRECTION("illuminate", "a point where R points at the camera",
            "section 5, step 1 (\"Remember that the camera is positioned at the origin\": V = normalise(-P))",
            null, SPECULAR, DIFFUSE),
    SPECULAR_WITH_I("illuminate", "a point with the light along its normal at distance 2",
            "section 5, \"The Phong illumination model\" (specular lighting: C_spec k_s I max(0, R.V)^n)", null,
            CAMERA_DIRECTION, FALL_OFF),
    V_UNIT("illuminate", "a point at distance 2 from the camera",
            "section 5, Figure 6(a): N, L, R and V should all be unit vectors", null, CAMERA_DIRECTION),
    REFLECTION("illuminate", "a point lit at an angle",
            "section 5, step 1 and footnote 1 (R is the mirror reflection of L in N: L.reflectIn(N))", null,
            CAMERA_DIRECTION),
    N_DOT_L_CLAMPED("illuminate", "a point with the light behind its surface",
            "section 5, Figure 6(b): make sure N.L is non-negative", null, DIFFUSE),
    R_DOT_V_CLAMPED("illuminate", "a point where R points away from the camera",
            "section 5, Figure 6(c): make sure R.V is non-negative", null, REFLECTION);

    private final String method;
    private final String situation;
    private final String section;
    private final String leftOpen;
    private final List<Probe> requires;

    Probe(String method, String situation, String section, String leftOpen, Probe... requires) {
        this.method = method;
        this.situation = situation;
        this.section = section;
        this.leftOpen = leftOpen;
        this.requires = List.of(requires);
    }

    /** The student's method the probe calls: intersectionWith or illuminate. */
    String method() {
        return method;
    }

    /** The input, in words: "a ray that starts inside a sphere". */
    String situation() {
        return situation;
    }

    /** The handout section the property comes from. */
    String section() {
        return section;
    }

    /** Why the course's tester may not mind (the handout leaves it open), or null. */
    String leftOpen() {
        return leftOpen;
    }

    /** A short name of the property, for the cohort's chart of common mistakes. */
    String label() {
        return method + ": " + switch (this) {
            case HIT -> "no hit";
            case MISS -> "hit on a miss";
            case POINTS_AWAY, BEHIND -> "hit behind the ray";
            case NEAREST_ROOT -> "not the nearest root";
            case POINT -> "wrong hit point";
            case NORMAL -> "wrong normal";
            case GRAZE -> "no hit on a graze";
            case INSIDE -> "no hit from inside";
            case ON_SURFACE -> "root s = 0 accepted";
            case PLACEHOLDER -> "returns C_diff";
            case SCALE -> "colour scaled by 255";
            case CHANNELS -> "channels crossed";
            case AMBIENT -> "ambient term";
            case DIFFUSE -> "diffuse term";
            case FALL_OFF -> "fall-off with distance";
            case SPECULAR -> "no specular term";
            case CAMERA_DIRECTION -> "V direction";
            case SPECULAR_WITH_I -> "specular without I";
            case V_UNIT -> "V not normalised";
            case REFLECTION -> "R direction";
            case N_DOT_L_CLAMPED -> "N.L not clamped";
            case R_DOT_V_CLAMPED -> "R.V not clamped";
        };
    }

    /** The probes that must hold for this one to be judged. */
    List<Probe> requires() {
        return requires;
    }
}
