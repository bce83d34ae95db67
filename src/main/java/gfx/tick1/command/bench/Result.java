package gfx.tick1.command.bench;

import gfx.tick1.engine.image.ImageDifference;

/** One variant's row of the report: how fast, and how far from the right image. */
record Result(String variant, String scene, int width, int height, int samples, int threads, Timing timing,
        String errorAgainst, ImageDifference error, int errorWidth, int errorHeight) {

    double megaRaysPerSecond() {
        return (double) width * height * samples / timing.median() / 1e3;
    }

    /** Root-mean-square error in levels: 255 / 10^(PSNR / 20). */
    double rmsError() {
        double psnr = error.psnr();
        return Double.isInfinite(psnr) ? 0 : 255 * Math.pow(10, -psnr / 20);
    }

    double differingShare() {
        return (double) error.differingPixels() / ((double) errorWidth * errorHeight);
    }
}
