package gfx.tick1.command.shared.behaviour;

import java.util.EnumSet;

/**
 * The catalogue {@code diagnose} compares an image with: the stages a student's image passes
 * through while following the handout, the correct image, and the mistakes students make.
 * {@code VariantRenderer} renders each one; this enum only names and explains them.
 */
public enum Variant {

    BACKGROUND_ONLY("background only", "",
            "no ray hits a sphere: Sphere.intersectionWith still returns an empty RaycastHit, or its test for a hit "
                    + "never succeeds",
            "section 4, \"Ray-sphere intersection code\" (the six-step algorithm)"),
    FLAT_COLOUR("flat colour", "Figure 4",
            "the spheres are found but not shaded: Renderer.illuminate still returns the object's colour, the "
                    + "starter code's placeholder",
            "section 5, \"Phong illumination code\""),
    AMBIENT_ONLY("ambient only", "Figure 5a",
            "only the ambient term C_diff I_a is returned: the diffuse and specular terms are missing",
            "section 5, \"The Phong illumination model\""),
    AMBIENT_DIFFUSE("ambient + diffuse", "like Figure 5b",
            "the specular term C_spec k_s I max(0, R.V)^n is missing, so there are no highlights",
            "section 5, \"The Phong illumination model\" (specular lighting)"),
    AMBIENT_WITHOUT_C_DIFF("ambient term without C_diff", "",
            "the ambient term is I_a alone instead of C_diff I_a, so every sphere gets the same grey wash whatever "
                    + "its colour",
            "section 5, \"The Phong illumination model\" (ambient lighting: C_diff I_a)"),
    NO_AMBIENT("no ambient term", "",
            "the ambient term C_diff I_a is missing: only the diffuse and specular terms are returned, so whatever "
                    + "the light does not reach is black",
            "section 5, \"The Phong illumination model\" (ambient lighting: C_diff I_a)"),
    SPECULAR_WITHOUT_I("specular term without I", "",
            "the specular term leaves out the light's illumination I (C_spec k_s max(0, R.V)^n instead of "
                    + "C_spec k_s I max(0, R.V)^n), so the highlights ignore the light's colour and distance",
            "section 5, \"The Phong illumination model\" (specular lighting: C_spec k_s I max(0, R.V)^n)"),
    COLOUR_TIMES_255("colour scaled by 255", "",
            "illuminate's colour is multiplied by 255, as if toRGB() wanted levels of 0 to 255; a colour's r, g, b "
                    + "run from 0 to 1 and toRGB() turns them into bytes itself, so every channel that is lit at all "
                    + "comes out 255",
            "section 2, \"Vector3\" (colours are x, y, z = r, g, b) and the starter code's Renderer.render, which "
                    + "converts with toRGB()"),
    COLOUR_OVER_255("colour divided by 255", "",
            "illuminate's colour is divided by 255, as if it were in levels of 0 to 255; it already runs from 0 to 1, "
                    + "so the spheres come out black",
            "section 2, \"Vector3\" (colours are x, y, z = r, g, b) and the starter code's Renderer.render, which "
                    + "converts with toRGB()"),
    CORRECT("correct", "Figure 1",
            "the full Phong model with the course's camera, intersection and byte conversion",
            "nothing: this is the image the tester expects"),
    UNNORMALISED_L_V("L and V not normalised", "Figure 6a",
            "L and V are used without normalising them, so N.L and R.V grow with the distances to the light and the "
                    + "camera and the image is too bright",
            "section 5, Figure 6(a): N, L, R and V should all be unit vectors"),
    UNCLAMPED_N_DOT_L("N.L not clamped", "Figure 6b",
            "the diffuse term uses N.L instead of max(0, N.L), so the sides facing away from the light get negative "
                    + "light and turn darker than the ambient light alone",
            "section 5, Figure 6(b): make sure N.L is non-negative"),
    UNCLAMPED_R_DOT_V("R.V not clamped", "Figure 6c",
            "the specular term uses (R.V)^n instead of max(0, R.V)^n; with the even exponent n = 10 negative values "
                    + "make false secondary highlights",
            "section 5, Figure 6(c): make sure R.V is non-negative"),
    FAR_ROOT("far root", "",
            "the intersection takes the farther root of the quadratic, so each pixel shows the back of its sphere, "
                    + "seen from inside",
            "section 4, steps 4 and 5: use the solution closest to the ray origin"),
    HIT_REJECTED_ON_A_NEGATIVE_ROOT("hit rejected when either root is negative", "",
            "the intersection gives no hit whenever one of the two roots is negative, so a sphere the camera is "
                    + "inside (one root behind the camera, one in front) is not seen at all; where the camera is "
                    + "outside every sphere the image is right, which is why tick1.xml passes",
            "section 4, steps 4 to 6: the hit is the nearest root with s > 0, whatever the sign of the other"),
    ROOTS_ACCEPTED_AT_ZERO("roots accepted at s >= 0", "",
            "the intersection accepts a root s = 0 (s1 >= 0 ? s1 : s2, then s >= 0), so a ray that starts on a "
                    + "sphere's surface hits it where it starts, at P = O; only a sphere whose surface passes "
                    + "exactly through the camera shows it, which is why tick1.xml passes",
            "section 4, steps 4 to 6: a hit is at s > 0, strictly"),
    UNCHECKED_NEGATIVE_SQUARE_ROOT("square root of a negative discriminant not checked", "",
            "Math.sqrt of a negative b^2 - 4ac is NaN; a RaycastHit at a NaN distance never beats the closest hit "
                    + "in Scene.findClosestIntersection, so the image is right, but only by luck",
            "section 4, step 2: if the discriminant is negative, return an empty RaycastHit", false),
    NO_FALL_OFF("no distance fall-off", "",
            "the light does not weaken with distance: I must be the light's colour times intensity / (4 pi d^2), "
                    + "which light.getIlluminationAt(distanceToLight) computes",
            "section 5, \"Diffuse lighting\" (I decreases over distance) and the given line "
                    + "Vector3 I = light.getIlluminationAt(distanceToLight)"),
    FALL_OFF_WITHOUT_4PI("fall-off without 4 pi", "",
            "the light falls off as intensity / d^2 without the 4 pi, so it is about 12.6 times too bright; "
                    + "light.getIlluminationAt(distanceToLight) has the right formula",
            "section 5, \"Phong illumination code\": the given line "
                    + "Vector3 I = light.getIlluminationAt(distanceToLight)"),
    // Two mistakes with one model: R.V changes sign either way, so no answer and no image tells
    // them apart, and the entry names both, V first as the handout's step 1 computes it first.
    V_AWAY_FROM_CAMERA("V pointing away from the camera or R negated", "",
            "either V points from the camera to the surface (P) instead of back to the camera (-P), or R is "
                    + "negated (the bounce of L, not its mirror reflection in N): R.V changes sign either way, so "
                    + "the two give the same answers, with highlights where the light is mirrored away from you",
            "section 5, step 1: \"Remember that the camera is positioned at the origin\", and footnote 1"),
    R_WRONG_WAY("R reflected the wrong way", "",
            "R is computed as N reflected in L (N.reflectIn(L)) instead of L reflected in N (L.reflectIn(N)), so "
                    + "the highlights are in the wrong place",
            "section 5, step 1 and footnote 1: R is the mirror reflection of L in N"),
    ROUNDED_BYTES("rounding instead of truncating", "",
            "colours are rounded to bytes instead of truncated towards zero, so many pixels are one level too "
                    + "bright; the course converts with an (int) cast, as Vector3.toRGB() does",
            "the starter code's Renderer.render: keep image.setRGB(x, y, colour.toRGB())"),
    UPSIDE_DOWN("image upside down", "",
            "the rows are written bottom to top: pixel row y = 0 is the top of the image, as in the starter code's "
                    + "Renderer.render and Camera.castRay",
            "section 4, first paragraph: ray casting is written for you in Camera and Renderer, keep render's loops"),
    RED_BLUE_SWAPPED("red and blue swapped", "",
            "red and blue are exchanged: a colour Vector3 holds r, g, b in x, y, z and toRGB() packs them as "
                    + "0xRRGGBB",
            "section 2, \"Vector3\": colours are x, y, z = r, g, b"),
    NORMAL_NOT_NORMALISED("normal not normalised", "",
            "the hit's normal is P - C without normalising it, so its length is the sphere's radius r and every "
                    + "term that uses N is r times too strong or too weak",
            "section 4, \"Ray-sphere intersection code\" (Vector3 normal = this.getNormalAt(point))"),
    ROOTS_IN_FLOAT("roots in float", "",
            "the roots s1 and s2 are kept in float, so the distance and the point are right to about 7 digits "
                    + "only, and a pixel here and there on a sphere's edge comes out differently",
            "section 4, step 3: compute s1 and s2 in double, as a, b and c are", false),
    DIVIDED_BY_2_TIMES_A("/ 2 * a for / (2 * a)", "",
            "the roots are computed as (-b +- sqrt(b^2 - 4ac)) / 2 * a, which divides by 2 and then multiplies "
                    + "by a; it is right only while D is a unit vector (a = 1), as the camera's rays are",
            "section 4, step 3: the quadratic formula divides by 2a", false),
    DISTANCE_ALWAYS_S1("distance always s1", "",
            "the hit's distance is always the first root s1, while its point is at the root chosen; the two "
                    + "differ only where the ray starts inside the sphere, where s1 is negative",
            "section 4, \"Ray-sphere intersection code\" (return the distance the ray travelled, s)", false),
    HANDOUT_SIX_STEPS("the handout's six steps, literally", "",
            "the hit is at s1 when s1 > 0 and s1 < s2, and there is none otherwise: a ray that starts inside a "
                    + "sphere or on its surface, or that grazes it, finds no hit. This is a correct answer",
            "section 4, steps 1 to 6", false),
    KD_SWAPPED_WITH_KS("k_d swapped with k_s", "",
            "the diffuse term uses k_s and the specular term k_d; the course's spheres all have k_d = k_s, so "
                    + "their images do not show it",
            "section 5, \"The Phong illumination model\" (C_diff k_d I max(0, N.L) + C_spec k_s I max(0, R.V)^n)",
            false),
    HIGHLIGHT_COLOURED("highlight coloured by C_diff", "",
            "the specular term uses the sphere's colour C_diff where C_spec is white, so the highlights take the "
                    + "sphere's colour",
            "section 5, \"The Phong illumination model\" (specular lighting: C_spec is white)"),
    DIFFUSE_WITHOUT_C_DIFF("diffuse term without C_diff", "",
            "the diffuse term is k_d I max(0, N.L) without the sphere's colour C_diff, so the lit sides are washed "
                    + "in the light's colour",
            "section 5, \"The Phong illumination model\" (diffuse lighting: C_diff k_d I max(0, N.L))"),
    L_FROM_THE_LIGHT("L pointing from the light", "",
            "L is normalise(P - L_pos), from the light to the point, where it should point from the point to the "
                    + "light, so the lit and unlit sides are exchanged",
            "section 5, step 1 (L is the direction to the light)");

    private final String label;
    private final String figure;
    private final String explanation;
    private final String reread;
    /**
     * Whether {@code diagnose} looks for the entry in images. Some cannot change an image at all
     * (an unchecked negative discriminant gives NaN distances, which the starter's Scene never
     * takes as the closest hit; the handout's six steps taken literally); others draw the
     * reference's image on the course's scenes, pixel for pixel or but for a pixel (k_d swapped
     * with k_s where every sphere has k_d = k_s, / 2 * a for the camera's unit directions, roots
     * in float, the distance s1 where no ray starts inside a sphere). {@code grade} and
     * {@code diff} still find every one of them by the answers of the methods.
     */
    private final boolean showsInImages;

    Variant(String label, String figure, String explanation, String reread) {
        this(label, figure, explanation, reread, true);
    }

    Variant(String label, String figure, String explanation, String reread, boolean showsInImages) {
        this.label = label;
        this.figure = figure;
        this.explanation = explanation;
        this.reread = reread;
        this.showsInImages = showsInImages;
    }

    /** A short name, with the handout figure that shows it, if any: "N.L not clamped (Figure 6b)". */
    public String title() {
        return figure.isEmpty() ? label : label + " (" + figure + ")";
    }

    /** One sentence (without a capital or a full stop) on what is wrong, for the winner of a diagnosis. */
    public String explanation() {
        return explanation;
    }

    /** Where in the handout to look. */
    public String reread() {
        return reread;
    }

    /** Where to look, as the words after "reread": "handout section 4, ...", or the starter code's member. */
    public String rereadWhere() {
        return where(reread);
    }

    /** {@code place} after "reread": a section is the handout's; the starter code is named as it is. */
    public static String where(String place) {
        return place.startsWith("section") ? "handout " + place : place;
    }

    /** The entries {@code diagnose} can tell apart by their images. */
    public static EnumSet<Variant> seenInImages() {
        EnumSet<Variant> seen = EnumSet.noneOf(Variant.class);
        for (Variant variant : values()) {
            if (variant.showsInImages) {
                seen.add(variant);
            }
        }
        return seen;
    }

    /** Whether this entry is a correct answer: the reference, or the handout's six steps taken literally. */
    public boolean isCorrect() {
        return this == CORRECT || this == HANDOUT_SIX_STEPS;
    }

    /** The student's method an entry changes, or where else it happens. */
    public enum Method { INTERSECTION_WITH, ILLUMINATE, RENDER, NONE }

    /** The method this entry changes: intersectionWith, illuminate, or neither (render, or the reference itself). */
    public Method method() {
        return switch (this) {
            case CORRECT -> Method.NONE;
            case BACKGROUND_ONLY, FAR_ROOT, HIT_REJECTED_ON_A_NEGATIVE_ROOT, ROOTS_ACCEPTED_AT_ZERO,
                    UNCHECKED_NEGATIVE_SQUARE_ROOT, NORMAL_NOT_NORMALISED, ROOTS_IN_FLOAT, DIVIDED_BY_2_TIMES_A,
                    DISTANCE_ALWAYS_S1, HANDOUT_SIX_STEPS -> Method.INTERSECTION_WITH;
            case ROUNDED_BYTES, UPSIDE_DOWN, RED_BLUE_SWAPPED -> Method.RENDER;
            default -> Method.ILLUMINATE;
        };
    }

    /**
     * Whether tick1.xml and the hidden scene can show the entry at all: these entries change only
     * what a ray does when it starts inside a sphere or on its surface, which neither scene has.
     */
    public boolean testedByTheCoursesScenes() {
        return switch (this) {
            case HIT_REJECTED_ON_A_NEGATIVE_ROOT, ROOTS_ACCEPTED_AT_ZERO, DISTANCE_ALWAYS_S1, HANDOUT_SIX_STEPS,
                    UNCHECKED_NEGATIVE_SQUARE_ROOT -> false;
            default -> true;
        };
    }
}
