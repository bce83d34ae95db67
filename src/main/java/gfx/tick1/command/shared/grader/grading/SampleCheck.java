package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.harness.SampleTrace;
import java.awt.image.BufferedImage;
import java.util.List;

/**
 * Whether an image comes from the student's own methods: the samples the harness traced through
 * their intersectionWith and illuminate ({@link SampleTrace}) against the pixels of the image
 * their Renderer returned. The trace is the child's, so it is read strictly: exactly one line a
 * sample, each six hex digits or "x", or the one line that says no thread could be started to trace
 * them. A pixel agrees within one level a channel.
 */
final class SampleCheck {

    /**
     * What the check found: NO_TRACE, that there is no trace of the samples to check; NO_THREAD, that the
     * harness could start no thread to trace them in, the run's threads being at the limit of processes and threads.
     */
    enum Result { AGREES, DISAGREES, NO_TRACE, NO_THREAD }

    private SampleCheck() {
    }

    static Result check(BufferedImage image, String trace) {
        if (trace == null) {
            return Result.NO_TRACE;
        }
        if (trace.equals(SampleTrace.NO_THREAD + "\n")) {
            return Result.NO_THREAD;
        }
        List<int[]> samples = SampleTrace.samples(image.getWidth(), image.getHeight());
        List<String> lines = trace.lines().limit(samples.size() + 1L).toList();
        if (lines.size() != samples.size()) {
            return Result.NO_TRACE;
        }
        for (int i = 0; i < samples.size(); i++) {
            String line = lines.get(i);
            if (!line.matches("[0-9a-f]{6}")) {
                return line.equals("x") ? Result.DISAGREES : Result.NO_TRACE;
            }
            int traced = Integer.parseInt(line, 16), drawn = image.getRGB(samples.get(i)[0], samples.get(i)[1]);
            for (int shift = 0; shift <= 16; shift += 8) {
                if (Math.abs((traced >> shift & 0xFF) - (drawn >> shift & 0xFF)) > 1) {
                    return Result.DISAGREES;
                }
            }
        }
        return Result.AGREES;
    }
}
