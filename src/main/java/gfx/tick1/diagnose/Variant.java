package gfx.tick1.diagnose;

import java.util.EnumSet;

/**
 * The catalogue {@code diagnose} compares an image with: the stages a student's image passes
 * through while following the handout, the correct image, and the mistakes students make.
 * {@link VariantRenderer} renders each one; this enum only names and explains them.
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
    V_AWAY_FROM_CAMERA("V pointing away from the camera", "",
            "V points from the camera to the surface (P) instead of back to the camera (-P), so highlights land "
                    + "where the light is mirrored away from you; negating R (reflecting -L, a bounce) gives the same "
                    + "picture",
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
            "section 2, \"Vector3\": colours are x, y, z = r, g, b");

    private final String label;
    private final String figure;
    private final String explanation;
    private final String reread;
    /**
     * Whether the mistake can change an image at all. One cannot: an unchecked negative
     * discriminant gives NaN distances, which the starter's Scene never takes as the closest hit.
     * {@code diagnose} leaves such entries out; {@code tick1 diff} still names them in code.
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

    public boolean isCorrect() {
        return this == CORRECT;
    }
}
