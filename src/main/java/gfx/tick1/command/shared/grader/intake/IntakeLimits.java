package gfx.tick1.command.shared.grader.intake;

/**
 * How much of a cohort's download the intake will read, so that a zip bomb or a huge upload costs a clear message,
 * not the grader's memory. Sizes count bytes actually inflated, never the sizes an archive's headers claim.
 *
 * @param maxFileBytes      the largest Sphere.java or Renderer.java read; a real one is a few KiB
 * @param maxNestedZipBytes the largest zip inside a student's folder that is opened (it is held in memory)
 * @param maxStudentBytes   the most bytes read for one student (their zips and the two files); beyond it, that
 *                          student's submission is a problem, so one student cannot stop a cohort being graded
 * @param maxEntries        the most entries one zip, or one student's unpacked folder, may have
 * @param maxTotalBytes     the most bytes read in one intake, all students together; beyond it, the download is
 *                          refused (a bound on the work a download can cause, well above any real cohort's)
 */
public record IntakeLimits(long maxFileBytes, long maxNestedZipBytes, long maxStudentBytes, int maxEntries,
        long maxTotalBytes) {

    private static final long MIB = 1024 * 1024;

    /** The limits of {@code tick1 grade --submissions}. */
    public static final IntakeLimits DEFAULT = new IntakeLimits(MIB, 64 * MIB, 256 * MIB, 65_535, 16 * 1024 * MIB);

    public IntakeLimits {
        if (maxFileBytes <= 0 || maxNestedZipBytes <= 0 || maxStudentBytes <= 0 || maxEntries <= 0
                || maxTotalBytes <= 0) {
            throw new IllegalArgumentException("intake limits must be positive");
        }
    }

    /** A size for messages: "1 GiB", "64 MiB", or bytes when not a whole number of MiB. */
    static String size(long bytes) {
        if (bytes % (1024 * MIB) == 0) {
            return bytes / (1024 * MIB) + " GiB";
        }
        return bytes % MIB == 0 ? bytes / MIB + " MiB" : bytes + " bytes";
    }
}
