package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.engine.scene.Intersection;
import java.util.List;

/**
 * The references a student's image may match ({@code tick1 grade --reference}): the image of the
 * handout's own intersection formula, that of tick1's robust intersection, or either of them.
 * They differ only on the hard scenes, where the handout's formula loses precision.
 */
public enum ReferenceChoice {
    handout, robust, either;

    /** The intersections whose references this choice compares with, in the order they are compared. */
    List<Intersection> intersections() {
        return switch (this) {
            case handout -> List.of(Intersection.HANDOUT);
            case robust -> List.of(Intersection.ROBUST);
            case either -> List.of(Intersection.HANDOUT, Intersection.ROBUST);
        };
    }
}
