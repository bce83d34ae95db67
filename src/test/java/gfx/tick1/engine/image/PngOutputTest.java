package gfx.tick1.engine.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * PNGs are written by ImageIO's writer, decode to exactly the image's pixels, and replace a file
 * whole or not at all; no temporary file outlives a run.
 */
class PngOutputTest {

    private static final BufferedImage IMAGE = new BufferedImage(4, 3, BufferedImage.TYPE_INT_RGB);

    @TempDir
    Path dir;

    private Path target;

    @BeforeEach
    void writeAnEarlierImage() throws IOException {
        target = EarlierImage.writeTo(dir.resolve("out.png"));
    }

    private List<Path> filesInDir() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.toList();
        }
    }

    private static BufferedImage image() {
        BufferedImage image = new BufferedImage(3, 2, BufferedImage.TYPE_INT_RGB);
        image.setRGB(1, 1, 0xABCDEF);
        return image;
    }

    @Test
    void writtenPngDecodesToTheSamePixels() throws IOException {
        Path target = dir.resolve("a.png");
        PngOutput.write(image(), target);
        assertThat(ImageIO.read(target.toFile()).getRGB(1, 1) & 0xFFFFFF).isEqualTo(0xABCDEF);
    }

    private static BufferedImage noisyGradient(int width, int height, long seed) {
        Random random = new Random(seed);
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int r = (x * 255 / Math.max(1, width - 1)) ^ random.nextInt(4);
                int g = y * 255 / Math.max(1, height - 1);
                image.setRGB(x, y, r << 16 | g << 8 | random.nextInt(256));
            }
        }
        return image;
    }

    @ParameterizedTest(name = "{0} x {1}, deflate level {2}")
    @CsvSource({"1, 1, 1", "3, 2, 1", "640, 480, 1", "17, 200, 1", "200, 129, 0", "64, 64, 2", "99, 65, 4",
        "31, 130, 9"})
    void theStreamDecodesToExactlyTheImagesPixelsAtEveryLevel(int width, int height, int level) throws IOException {
        BufferedImage image = noisyGradient(width, height, width * 31L + height);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PngOutput.write(image, out, level);

        BufferedImage decoded = ImageIO.read(new ByteArrayInputStream(out.toByteArray()));
        assertThat(decoded).as("ImageIO could not read the PNG").isNotNull();
        ImageDifference difference = ImageDifference.between(image, decoded);
        assertThat(difference.differingPixels()).as(difference.summary()).isZero();
    }

    @Test
    void aStreamThatFailsPartWayGivesItsOwnReasonNotImageIosWrapper() {
        OutputStream full = new OutputStream() {
            private int written;

            @Override
            public void write(int b) throws IOException {
                if (++written > 100) {
                    throw new IOException("No space left on device");
                }
            }
        };
        assertThatThrownBy(() -> PngOutput.write(noisyGradient(64, 64, 1), full))
                .isInstanceOf(IOException.class).hasMessage("No space left on device");
    }

    @Test
    void pngsAreWrittenByImageIoNotByHandWrittenDeflateOrChunkCode() throws IOException {
        Path sources = Path.of("src", "main", "java");
        assumeTrue(Files.isDirectory(sources), "needs the project's sources");
        try (Stream<Path> files = Files.walk(sources)) {
            List<String> offenders = files.filter(file -> file.toString().endsWith(".java"))
                    .filter(file -> {
                        try {
                            return Pattern.compile("\\b(Deflater|DeflaterOutputStream|CRC32|Adler32)\\b")
                                    .matcher(Files.readString(file)).find();
                        } catch (IOException e) {
                            throw new UncheckedIOException(e);
                        }
                    })
                    .map(file -> sources.relativize(file).toString()).toList();
            assertThat(offenders).as("sources that deflate or checksum by hand").isEmpty();
        }
    }

    @Test
    void replacesAnExistingFileAndLeavesNoTemporaryFile() throws IOException {
        // target already holds an earlier image (see writeAnEarlierImage).
        PngOutput.write(image(), target);
        assertThat(ImageIO.read(target.toFile())).isNotNull();
        assertThat(filesInDir()).containsExactly(target);
    }

    @Test
    void aMissingDirectoryIsReportedAndNothingIsCreated() {
        Path target = dir.resolve("missing").resolve("a.png");
        assertThatThrownBy(() -> PngOutput.write(image(), target)).isInstanceOf(IOException.class)
                .hasMessageContaining("does not exist");
        assertThat(dir.resolve("missing")).doesNotExist();
    }

    @Test
    void theImageIsEncodedIntoAHiddenTemporaryFileBesideTheTarget() throws IOException {
        List<Path> seenWhileEncoding = new ArrayList<>();
        PngOutput.write(IMAGE, target, (image, out) -> {
            seenWhileEncoding.addAll(filesInDir());
            PngOutput.write(image, out);
        });
        assertThat(seenWhileEncoding).hasSize(2).contains(target)
                .anySatisfy(p -> assertThat(p.getFileName().toString()).startsWith(".out.png.").endsWith(".tmp"));
        assertThat(ImageIO.read(target.toFile()).getWidth()).isEqualTo(4);
        assertThat(filesInDir()).containsExactly(target);
    }

    @Test
    void aWriteThatFailsPartWayLeavesTheEarlierImageAndNoTemporaryFile() {
        assertThatThrownBy(() -> PngOutput.write(IMAGE, target, (image, out) -> {
            out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G'});
            throw new IOException("No space left on device");
        })).isInstanceOf(IOException.class).hasMessage("No space left on device");
        assertThat(target).hasBinaryContent(EarlierImage.bytes());
        assertThat(dir.toFile().list()).containsExactly("out.png");
    }

    @Test
    void aFailureOutsideIoAlsoLeavesTheEarlierImageAndNoTemporaryFile() {
        assertThatThrownBy(() -> PngOutput.write(IMAGE, target, (image, out) -> {
            throw new IllegalStateException("a bug in the encoder");
        })).isInstanceOf(IllegalStateException.class);
        assertThat(target).hasBinaryContent(EarlierImage.bytes());
        assertThat(dir.toFile().list()).containsExactly("out.png");
    }

    @Test
    void aDirectoryThatIsAFileIsNamedAsSuch() throws IOException {
        Path file = dir.resolve("notes.txt");
        Files.writeString(file, "not a directory");
        assertThatThrownBy(() -> PngOutput.write(IMAGE, file.resolve("out.png")))
                .hasMessage(file + " is not a directory");
    }

    @Test
    void anUnwritableDirectoryIsNamedAndLeftAsItWas() throws IOException {
        assumeTrue(FileSystems.getDefault().supportedFileAttributeViews().contains("posix"), "POSIX permissions");
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            assumeTrue(!Files.isWritable(dir), "root may write anywhere: nothing to test");
            assertThatThrownBy(() -> PngOutput.write(IMAGE, target))
                    .hasMessage("cannot create a file in " + dir + " (permission denied)");
            assertThat(target).hasBinaryContent(EarlierImage.bytes());
        } finally {
            Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    @Test
    void theFinishedImageHasOrdinaryPermissionsNotPrivateTemporaryOnes() throws IOException {
        assumeTrue(FileSystems.getDefault().supportedFileAttributeViews().contains("posix"), "POSIX permissions");
        Files.delete(target);
        PngOutput.write(IMAGE, target);
        // Whatever the umask, a new file is readable by its owner and more than its owner.
        assertThat(Files.getPosixFilePermissions(target))
                .contains(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE)
                .containsAnyOf(PosixFilePermission.GROUP_READ, PosixFilePermission.OTHERS_READ);
    }

    /**
     * A separate JVM starts writing the image, stalls part way (as a slow disk would) and is sent
     * SIGINT, as Ctrl-C sends: its shutdown hook must delete the temporary file.
     */
    @Test
    void anInterruptedWriteLeavesTheEarlierImageAndNoTemporaryFile() throws Exception {
        Path kill = Path.of("/bin/kill");
        assumeTrue(Files.isExecutable(kill), "needs /bin/kill to send SIGINT");
        assumeFalse(sigintIgnored(), "SIGINT is ignored here (the tests were started in the background, with & or "
                + "nohup), and so in the writer's JVM too: run them in the foreground to test Ctrl-C");
        Process process = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), StalledWrite.class.getName(), target.toString())
                .redirectErrorStream(true).start();
        try {
            // StalledWrite prints one line once the temporary file holds part of the PNG.
            String line = new String(process.getInputStream().readNBytes(StalledWrite.READY.length() + 1),
                    StandardCharsets.UTF_8);
            assertThat(line).startsWith(StalledWrite.READY);
            assertThat(dir.toFile().list()).hasSize(2);

            new ProcessBuilder(kill.toString(), "-INT", Long.toString(process.pid())).start().waitFor();
            assertThat(process.waitFor(60, TimeUnit.SECONDS)).as("the writer stopped").isTrue();
        } finally {
            process.destroyForcibly();
        }
        assertThat(target).hasBinaryContent(EarlierImage.bytes());
        assertThat(dir.toFile().list()).containsExactly("out.png");
    }

    /**
     * Whether this process ignores SIGINT, as a child of a shell's background job does: a JVM started
     * so ignores it too, and Ctrl-C cannot be tested (bit 2 of SigIgn in /proc/self/status).
     */
    private static boolean sigintIgnored() throws IOException {
        Path status = Path.of("/proc/self/status");
        if (!Files.isReadable(status)) {
            return false;
        }
        return Files.readAllLines(status).stream().filter(line -> line.startsWith("SigIgn:"))
                .map(line -> Long.parseUnsignedLong(line.substring("SigIgn:".length()).strip(), 16))
                .anyMatch(mask -> (mask & (1L << 1)) != 0);
    }

    /** The other JVM of the test above. */
    static final class StalledWrite {
        static final String READY = "temporary file written";

        public static void main(String[] args) throws Exception {
            PngOutput.write(IMAGE, Path.of(args[0]), (image, out) -> {
                out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G'});
                out.flush();
                System.out.println(READY);
                System.out.flush();
                try {
                    Thread.sleep(Long.MAX_VALUE);
                } catch (InterruptedException e) {
                    throw new IOException(e);
                }
            });
        }
    }

    @Test
    void aSymbolicLinkStaysALinkAndTheFileItPointsToIsReplaced() throws IOException {
        Path real = Files.createDirectory(dir.resolve("real")).resolve("target.png");
        Files.writeString(real, "old");
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), Path.of("real", "target.png"));
        PngOutput.write(image(), link);
        assertThat(Files.isSymbolicLink(link)).as("the link itself").isTrue();
        assertThat(ImageIO.read(real.toFile())).as("the file it points to").isNotNull();
    }

    @Test
    void aLinkToAFileNotYetThereCreatesThatFile() throws IOException {
        Path real = Files.createDirectory(dir.resolve("real")).resolve("new.png");
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), real);
        PngOutput.write(image(), link);
        assertThat(Files.isSymbolicLink(link)).isTrue();
        assertThat(ImageIO.read(real.toFile())).isNotNull();
    }

    @Test
    void aNamedPipeReceivesThePngAndIsNotReplacedByAFile() throws Exception {
        Path fifo = dir.resolve("pipe.png");
        Process mkfifo;
        try {
            mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        } catch (IOException e) {
            assumeTrue(false, "skipped: no mkfifo on this machine");
            return;
        }
        assumeTrue(mkfifo.waitFor(10, TimeUnit.SECONDS) && mkfifo.exitValue() == 0, "skipped: mkfifo failed");
        byte[][] received = new byte[1][];
        Thread reader = new Thread(() -> {
            try {
                received[0] = Files.readAllBytes(fifo);
            } catch (IOException e) {
                received[0] = new byte[0];
            }
        });
        reader.start();
        PngOutput.write(image(), fifo);
        reader.join(10_000);
        assertThat(Files.isRegularFile(fifo)).as("the pipe is still a pipe").isFalse();
        assertThat(ImageIO.read(new java.io.ByteArrayInputStream(received[0]))).as("what the reader got").isNotNull();
    }
}
