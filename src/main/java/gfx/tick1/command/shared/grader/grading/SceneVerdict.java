package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.sandbox.NoImage;

/**
 * What one scene came to, as a type: the cohort's category for it is made from this, never from
 * the words that explain it, so rewording a message cannot move a student to another bar of the
 * chart.
 */
sealed interface SceneVerdict {

    /** The chart's category of a failure (a pass has none to show). */
    String category();

    /** The image is the reference's, and their own methods give its sampled pixels. */
    record Passed() implements SceneVerdict {
        @Override
        public String category() {
            return Explainer.PASSED;
        }
    }

    /**
     * An image whose pixels are not the reference's: the category (the catalogue entry it is exactly,
     * else the first tested finding's, else that tick1 does not recognise it), and the row's sentence
     * naming the exact catalogue match, or null when none matches.
     */
    record WrongPixels(String category, String exactly) implements SceneVerdict {
    }

    /** The reference's image, but their own methods give other colours, or could not be asked. */
    record NotFromTheCode() implements SceneVerdict {
        @Override
        public String category() {
            return Explainer.NOT_FROM_CODE_LABEL;
        }
    }

    /** No image, and why. */
    record Missing(NoImage why) implements SceneVerdict {
        @Override
        public String category() {
            return switch (why) {
                case TIME_LIMIT -> Explainer.TIME_LIMIT;
                case THREW -> Explainer.EXCEPTION;
                default -> Explainer.CRASHED;
            };
        }
    }
}
