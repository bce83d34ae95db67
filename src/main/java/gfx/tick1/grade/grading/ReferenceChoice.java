package gfx.tick1.grade.grading;

/**
 * The references a student's image may match ({@code tick1 grade --reference}): the image of the
 * handout's own intersection formula, that of tick1's robust intersection, or either of them.
 * They differ only on the hard scenes, where the handout's formula loses precision.
 */
public enum ReferenceChoice {
    handout, robust, either
}
