package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.model.Category;
import gfx.tick1.command.shared.grader.sandbox.NoImage;

/**
 * What one scene came to, as a type: the cohort's category for it is made from this, never from
 * the words that explain it, so rewording a message cannot move a student to another bar of the
 * chart.
 */
sealed interface SceneVerdict {

    /** The chart's category of a failure (a pass has none to show). */
    Category category();

    /** The image is the reference's, and their own methods give its sampled pixels. */
    record Passed() implements SceneVerdict {
        @Override
        public Category category() {
            return Category.Outcome.PASSED;
        }
    }

    /**
     * An image whose pixels are not the reference's: the category (the catalogue entry it is exactly,
     * else the first tested finding's, else that tick1 does not recognise it), the row's sentence
     * naming the exact catalogue match, or null when none matches, and where the methods differ
     * from ours on a differing pixel's ray, when that is what showed it (else null).
     */
    record WrongPixels(Category category, String exactly, String pixel) implements SceneVerdict {

        /** Without a differing pixel's counterexample. */
        WrongPixels(Category category, String exactly) {
            this(category, exactly, null);
        }
    }

    /** The reference's image, but their own methods give other colours, or could not be asked. */
    record NotFromTheCode() implements SceneVerdict {
        @Override
        public Category category() {
            return Category.Outcome.NOT_FROM_THE_CODE;
        }
    }

    /** No image, and why. */
    record Missing(NoImage why) implements SceneVerdict {
        @Override
        public Category category() {
            return switch (why) {
                case TIME_LIMIT -> Category.Outcome.TIME_LIMIT;
                case THREW -> Category.Outcome.EXCEPTION;
                default -> Category.Outcome.CRASHED;
            };
        }
    }
}
