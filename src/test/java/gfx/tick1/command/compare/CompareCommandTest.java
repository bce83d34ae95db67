package gfx.tick1.command.compare;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.engine.image.HeatMapLegend;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.image.PngOutput;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code tick1 compare} through the real entry point. */
class CompareCommandTest {

    @TempDir
    Path dir;

    private Path png(String name, int width, int height, int rgb, int... changedPixelsAndColours) throws IOException {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, rgb);
            }
        }
        for (int i = 0; i < changedPixelsAndColours.length; i += 3) {
            image.setRGB(changedPixelsAndColours[i], changedPixelsAndColours[i + 1], changedPixelsAndColours[i + 2]);
        }
        Path file = dir.resolve(name);
        PngOutput.write(image, file);
        return file;
    }

    @Test
    void identicalImagesExitZero() throws IOException {
        Path a = png("a.png", 8, 6, 0x336699), b = png("b.png", 8, 6, 0x336699);
        CliRun run = CliRun.of("compare", a.toString(), b.toString());
        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(run.out()).contains("pixels differing: 0 of 48", "PSNR:             infinite",
                "SAME: identical pixel for pixel");
        assertThat(run.err()).isEmpty();
    }

    @Test
    void oneDifferentPixelExitsOneWithItsFigures() throws IOException {
        Path a = png("a.png", 8, 6, 0x336699), b = png("b.png", 8, 6, 0x336699, 5, 2, 0x33669F);
        CliRun run = CliRun.of("compare", a.toString(), b.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(CompareCommand.EXIT_DIFFERENT);
        assertThat(run.out()).contains("pixels differing: 1 of 48", "max difference:   R 0, G 0, B 6 levels",
                "bounding box:     5,2 - 5,2", "DIFFERENT: 1 pixel differs");
    }

    @Test
    void differencesWithinTheToleranceExitZero() throws IOException {
        Path a = png("a.png", 8, 6, 0x336699), b = png("b.png", 8, 6, 0x336699, 0, 0, 0x34669A);
        assertThat(CliRun.of("compare", "--tolerance", "1", a.toString(), b.toString()).status()).isZero();
        assertThat(CliRun.of("compare", "--tolerance", "0", a.toString(), b.toString()).status()).isEqualTo(1);
    }

    @Test
    void diffWritesAHeatMapOfTheSameSize() throws IOException {
        Path a = png("a.png", 8, 6, 0x336699), b = png("b.png", 8, 6, 0x336699, 1, 1, 0xFFFFFF);
        Path heat = dir.resolve("heat.png");
        CliRun run = CliRun.of("compare", a.toString(), b.toString(), "--diff", heat.toString());
        assertThat(run.out()).contains("heat map: " + heat);
        BufferedImage map = ImageIO.read(heat.toFile());
        assertThat(map.getWidth()).isEqualTo(8);
        assertThat(map.getHeight()).isEqualTo(6);
    }

    @Test
    void aHeatMapWideEnoughForALegendHasItInAStripBelowTheComparedPixels() throws IOException {
        Path a = png("a.png", 320, 200, 0x336699), b = png("b.png", 320, 200, 0x336699, 5, 7, 0x346699);
        Path heat = dir.resolve("heat.png");
        CliRun.of("compare", a.toString(), b.toString(), "--diff", heat.toString());
        BufferedImage map = ImageIO.read(heat.toFile());
        assertThat(map.getWidth()).isEqualTo(320);
        assertThat(map.getHeight()).isEqualTo(200 + HeatMapLegend.HEIGHT);
        int red = map.getRGB(5, 7) >> 16 & 0xFF, green = map.getRGB(5, 7) >> 8 & 0xFF;
        assertThat(red).as("the differing pixel keeps its place above the legend").isGreaterThan(green);
    }

    @Test
    void theHeatMapSaysWhichWayAPixelIsOffUnlessUnsignedIsAsked() throws IOException {
        Path a = png("a.png", 320, 200, 0x336699), b = png("b.png", 320, 200, 0x336699, 5, 7, 0x326699);
        Path signed = dir.resolve("signed.png"), unsigned = dir.resolve("unsigned.png");
        CliRun.of("compare", a.toString(), b.toString(), "--diff", signed.toString());
        CliRun.of("compare", a.toString(), b.toString(), "--diff", unsigned.toString(), "--unsigned");

        assertThat(ImageIO.read(signed.toFile()).getRGB(5, 7) & 0xFFFFFF).as("a pixel 1 level darker, by default")
                .isEqualTo(ImageDifference.darkerColour(1));
        assertThat(ImageIO.read(unsigned.toFile()).getRGB(5, 7) & 0xFFFFFF).as("the same with --unsigned")
                .isEqualTo(ImageDifference.heatColour(1));
    }

    @Test
    void differentSizesGiveOneLineAndExitTwo() throws IOException {
        Path a = png("a.png", 8, 6, 0), b = png("b.png", 6, 8, 0);
        CliRun run = CliRun.of("compare", a.toString(), b.toString());
        assertThat(run.status()).isEqualTo(CompareCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).isEqualTo("tick1 compare: image sizes differ: expected 8 x 6, actual 6 x 8"
                + System.lineSeparator());
        assertThat(run.out()).isEmpty();
    }

    @Test
    void anUnreadableOrMissingImageGivesOneLineAndExitTwo() throws IOException {
        Path good = png("a.png", 8, 6, 0);
        Path text = dir.resolve("notes.png");
        Files.writeString(text, "not a picture");
        Path truncated = dir.resolve("cut.png");
        byte[] bytes = Files.readAllBytes(good);
        Files.write(truncated, java.util.Arrays.copyOf(bytes, bytes.length / 2));
        for (Path bad : new Path[] {text, truncated, dir.resolve("missing.png"), dir}) {
            CliRun run = CliRun.of("compare", good.toString(), bad.toString());
            assertThat(run.status()).as(run.transcript()).isEqualTo(CompareCommand.EXIT_CANNOT_COMPARE);
            assertThat(run.err()).startsWith("tick1 compare: " + bad + ": ").doesNotContain("\tat ");
            assertThat(run.err().lines()).hasSize(1);
        }
    }

    /** A named pipe in the test's folder, made by mkfifo; the test is skipped where there is none. */
    private Path fifo(String name) throws IOException, InterruptedException {
        Path fifo = dir.resolve(name);
        Process mkfifo;
        try {
            mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        } catch (IOException e) {
            org.junit.jupiter.api.Assumptions.abort("needs mkfifo to make a named pipe");
            throw e;
        }
        org.junit.jupiter.api.Assumptions.assumeTrue(mkfifo.waitFor() == 0, "mkfifo can make a named pipe here");
        return fifo;
    }

    /**
     * Writes {@code start} into {@code fifo}, then {@code more} (if any) over and over until the reader stops; counts
     * the bytes written.
     */
    private static Thread feed(Path fifo, byte[] start, byte[] more, java.util.concurrent.atomic.AtomicLong written) {
        Thread writer = new Thread(() -> {
            try (java.io.OutputStream out = Files.newOutputStream(fifo)) {
                out.write(start);
                written.addAndGet(start.length);
                while (more.length > 0) {
                    out.write(more);
                    written.addAndGet(more.length);
                }
            } catch (IOException e) {
                // The reader closed the pipe: the end of the feed.
            }
        });
        writer.setDaemon(true);
        writer.start();
        return writer;
    }

    @Test
    void aPngReadThroughANamedPipeIsCompared() throws IOException, InterruptedException {
        // Noise, so that the file is larger than a stream's buffer.
        BufferedImage noise = new BufferedImage(64, 48, BufferedImage.TYPE_INT_RGB);
        java.util.Random random = new java.util.Random(1);
        for (int y = 0; y < noise.getHeight(); y++) {
            for (int x = 0; x < noise.getWidth(); x++) {
                noise.setRGB(x, y, random.nextInt(1 << 24));
            }
        }
        Path good = dir.resolve("noise.png");
        PngOutput.write(noise, good);
        assertThat(Files.size(good)).as("the PNG's size").isGreaterThan(8192);
        Path pipe = fifo("piped.png");
        feed(pipe, Files.readAllBytes(good), new byte[0], new java.util.concurrent.atomic.AtomicLong());
        CliRun run = CliRun.of("compare", good.toString(), pipe.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(CompareCommand.EXIT_SAME);
    }

    /** A PNG chunk: its length, type, data and CRC. */
    private static byte[] chunk(String type, byte[] data) {
        java.nio.ByteBuffer chunk = java.nio.ByteBuffer.allocate(12 + data.length).putInt(data.length);
        java.util.zip.CRC32 crc = new java.util.zip.CRC32();
        byte[] name = type.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
        crc.update(name);
        crc.update(data);
        return chunk.put(name).put(data).putInt((int) crc.getValue()).array();
    }

    @Test
    void aPngThatNeverEndsIsReadNoFurtherThanTheBoundAndRefusedInOneLine() throws IOException, InterruptedException {
        Path good = png("a.png", 8, 6, 0);
        Path pipe = fifo("endless.png");
        // A 640 x 480 PNG's signature and header, then image data chunks without end.
        byte[] start = java.nio.ByteBuffer.allocate(8 + 25).put(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n',
            0x1A, '\n'}).put(chunk("IHDR", java.nio.ByteBuffer.allocate(13).putInt(640).putInt(480)
                .put(new byte[] {8, 2, 0, 0, 0}).array())).array();
        java.util.concurrent.atomic.AtomicLong written = new java.util.concurrent.atomic.AtomicLong();
        feed(pipe, start, chunk("IDAT", new byte[1 << 16]), written);

        CliRun run = CliRun.of("compare", good.toString(), pipe.toString());

        assertThat(run.status()).as(run.transcript()).isEqualTo(CompareCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).as(run.transcript()).isEqualTo("tick1 compare: " + pipe + ": larger than "
                + gfx.tick1.engine.io.BoundedFile.size(gfx.tick1.engine.image.PngInput.MAX_BYTES)
                + ", expected a PNG image" + System.lineSeparator());
        assertThat(written.get()).as("bytes written before the reader stopped")
                .isLessThan(gfx.tick1.engine.image.PngInput.MAX_BYTES + 4 * (1 << 20));
    }

    /** A JPEG of a render, as an image viewer's "save as" or a screenshot tool gives. */
    private Path jpeg(String name) throws IOException {
        BufferedImage image = new BufferedImage(8, 6, BufferedImage.TYPE_INT_RGB);
        Path file = dir.resolve(name);
        assertThat(ImageIO.write(image, "jpeg", file.toFile())).isTrue();
        return file;
    }

    @Test
    void aJpegIsRefusedInOneLineThatSaysWhyWhateverItsName() throws IOException {
        Path good = png("a.png", 8, 6, 0);
        for (Path jpeg : new Path[] {jpeg("real.jpg"), jpeg("named-as.png")}) {
            CliRun run = CliRun.of("compare", good.toString(), jpeg.toString());
            assertThat(run.status()).as(run.transcript()).isEqualTo(CompareCommand.EXIT_CANNOT_COMPARE);
            assertThat(run.err()).as(run.transcript()).isEqualTo("tick1 compare: " + jpeg + ": a JPEG image, not a "
                    + "PNG: JPEG's compression changes pixels, so it cannot match a render pixel for pixel; save the "
                    + "image as PNG" + System.lineSeparator());
            assertThat(run.out()).as("no figures for a JPEG").isEmpty();
        }
    }

    @Test
    void aHeatMapNamedAsAnotherFormatIsRefusedBeforeAnythingIsWritten() throws IOException {
        Path a = png("a.png", 8, 6, 0), b = png("b.png", 8, 6, 0x010101);
        CliRun run = CliRun.of("compare", a.toString(), b.toString(), "--diff", dir.resolve("d.jpg").toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(CompareCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).startsWith("tick1 compare: --diff " + dir.resolve("d.jpg") + ": the heat map is a PNG; "
                + "name it " + dir.resolve("d.png"));
        assertThat(dir.resolve("d.jpg")).doesNotExist();
    }

    @Test
    void aMissingArgumentIsAUsageError() {
        CliRun run = CliRun.of("compare", "only-one.png");
        assertThat(run.status()).isEqualTo(2);
        assertThat(run.err()).startsWith("tick1 compare: ").contains("(see tick1 compare --help)");
    }
}
