package gfx.tick1.command.bench;

import java.util.List;

/**
 * How much a benchmark run does: the frames and repetitions of the in-process variants, the crowds,
 * how many times each fresh process is timed, the big frame of the C yardstick's goal and the
 * cohort's size. The quick plan is the full one made smaller in every part, so that it stays cheap
 * on a two-core machine that other work shares, and still measures all three goals, more coarsely
 * (docs/benchmark.md has what it costs).
 *
 * @param width the in-process tick1.xml frame's width; {@code height} its height
 * @param errorWidth the smaller frame on which each variant's error is measured; {@code errorHeight} its height
 * @param warmups untimed in-process frames before the timed ones ({@code runs})
 * @param crowds the crowd scenes' sphere counts, rendered at {@code crowdWidth} x 3/4 of it
 * @param pairedRuns timed runs of tick1 and of the course code, taken in turn (the first goal's ratio)
 * @param singleRuns timed runs of each other fresh process (phases, the handout-style run, the crowds)
 * @param warmUpProcesses whether each command is run once untimed first, so that its files are in the cache
 * @param bigWidth the C yardstick's frame (with 4 samples); {@code bigHeight} its height
 * @param bigRuns timed runs of tick1 and of the C tracer at that frame, taken in turn
 * @param cohort how many submissions the cohort's grade has
 * @param studentRuns timed runs of each of the one-student section's runs, taken in turn
 */
record BenchPlan(int width, int height, int errorWidth, int errorHeight, int warmups, int runs,
        List<Integer> crowds, int crowdWidth, int pairedRuns, int singleRuns, boolean warmUpProcesses,
        int bigWidth, int bigHeight, int bigRuns, int cohort, int studentRuns) {

    /** The full run, for people: the goals' own frames, medians of many runs, a year's cohort. */
    static final BenchPlan FULL = new BenchPlan(3840, 2160, 640, 480, 6, 7, List.of(1_000, 10_000), 640, 11, 11,
            true, 3840, 2160, 7, 100, 5);

    /**
     * The quick run, for CI and a first look: in process, tick1.xml at 320 x 240 and the crowd at 160 x 120; each fresh
     * process once (the goal's pairs twice) with no untimed run before it, since the fresh process
     * costs most of the CPU a quick run spends; the big frame at 1920 x 1080; a cohort of one
     * submission for each of the two jobs a two-core machine grades at once; each of one student's runs once.
     */
    static final BenchPlan QUICK = new BenchPlan(320, 240, 160, 120, 1, 3, List.of(1_000), 160, 2, 1, false,
            1920, 1080, 1, 2, 1);

    /** The same plan with other in-process repetitions (the crowds' brute force takes long a frame). */
    BenchPlan withRuns(int fewerWarmups, int fewerRuns) {
        return new BenchPlan(width, height, errorWidth, errorHeight, fewerWarmups, fewerRuns, crowds, crowdWidth,
                pairedRuns, singleRuns, warmUpProcesses, bigWidth, bigHeight, bigRuns, cohort, studentRuns);
    }
}
