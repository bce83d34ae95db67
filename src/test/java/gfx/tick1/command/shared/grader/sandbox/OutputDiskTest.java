package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assumptions.assumeThat;

import java.io.IOException;
import java.io.OutputStream;
import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A run's output folder as a file system of its own: what the kernel refuses, what the grader
 * counts that no walk of names sees, and what is left when it is unmounted. (Mounting needs root.)
 */
class OutputDiskTest {

    private static final byte[] MIB = new byte[1 << 20];

    @TempDir
    Path dir;

    private Path folder;

    @BeforeEach
    void anEmptyFolderThatCanBeMountedOn() throws IOException {
        folder = Files.createDirectory(dir.resolve("output"));
        assumeThat(OutputDisk.canMount(Files.createDirectory(dir.resolve("scratch"))))
                .as("a tmpfs can be mounted here (as root)").isTrue();
    }

    @Test
    void writingBeyondItsSizeIsRefusedByTheKernel() throws IOException {
        try (OutputDisk disk = OutputDisk.mount(folder, 0);
                OutputStream out = Files.newOutputStream(folder.resolve("big"))) {
            assertThatThrownBy(() -> {
                for (long written = 0; written <= OutputDisk.BYTES; written += MIB.length) {
                    out.write(MIB);
                }
            }).as("writing one MiB more than the file system's size").isInstanceOf(IOException.class);
            assertThat(disk.overCap()).as("what the grader says of it").isEqualTo(OutputCount.TOO_MANY_BYTES);
        }
    }

    @Test
    void aFileDeletedWhileHeldOpenCountsAgainstTheCap() throws IOException {
        try (OutputDisk disk = OutputDisk.mount(folder, 0);
                RandomAccessFile held = new RandomAccessFile(folder.resolve("held").toFile(), "rw")) {
            Files.delete(folder.resolve("held"));
            for (long written = 0; written <= OutputCount.BYTES_CAP; written += MIB.length) {
                held.write(MIB);
            }
            assertThat(OutputCount.overCap(folder)).as("the walk of names").isNull();
            assertThat(disk.overCap()).as("the file system's own count").isEqualTo(OutputCount.TOO_MANY_BYTES);
        }
    }

    @Test
    void makingMoreFilesThanItsInodesIsRefusedByTheKernel() throws IOException {
        try (OutputDisk disk = OutputDisk.mount(folder, 0)) {
            int made = 0;
            try {
                for (; made <= OutputDisk.INODES; made++) {
                    Files.createFile(folder.resolve(Integer.toString(made)));
                }
            } catch (IOException e) {
                // No inode left.
            }
            assertThat(made).as("files made beside the folder itself").isEqualTo(OutputDisk.INODES - 1);
            assertThat(disk.overCap()).as("what the grader says of it").isEqualTo(OutputCount.TOO_MANY_ENTRIES);
        }
    }

    @Test
    void aRunBelowTheCapsIsNotStopped() throws IOException {
        try (OutputDisk disk = OutputDisk.mount(folder, 0)) {
            Files.write(folder.resolve("image.png"), MIB);
            assertThat(disk.overCap()).isNull();
        }
    }

    @Test
    void aProgramWrittenThereCannotBeStarted() throws IOException {
        try (OutputDisk disk = OutputDisk.mount(folder, 0)) {
            Path program = Files.copy(Path.of("/bin/true"), disk.folder().resolve("true"));
            assertThat(program.toFile().setExecutable(true)).as("the copy marked executable").isTrue();
            assertThatThrownBy(() -> new ProcessBuilder(program.toString()).start().waitFor())
                    .as("starting a program written there").isInstanceOf(IOException.class)
                    .hasMessageContaining("Permission denied");
        }
    }

    @Test
    void unmountingLeavesTheFolderEmptyOnTheHostsDisk() throws IOException {
        Object hostDevice = Files.getAttribute(dir, "unix:dev");
        try (OutputDisk mounted = OutputDisk.mount(folder, 0)) {
            assertThat(mounted.folder()).isEqualTo(folder);
            Files.write(folder.resolve("image.png"), MIB);
            assertThat(Files.getAttribute(folder, "unix:dev")).as("the folder's device while mounted")
                    .isNotEqualTo(hostDevice);
        }
        assertThat(Files.getAttribute(folder, "unix:dev")).as("the folder's device afterwards").isEqualTo(hostDevice);
        try (var left = Files.list(folder)) {
            assertThat(left).as("what is left in the folder").isEmpty();
        }
    }

    @Test
    void deletingTheWorkFolderUnmountsARunsFileSystemStillMountedInIt() throws IOException {
        Path work = Files.createDirectory(dir.resolve("work"));
        Path output = Files.createDirectory(work.resolve("output"));
        OutputDisk.mount(output, 0);
        Files.write(output.resolve("image.png"), MIB);

        assertThat(WorkFolder.delete(work)).as("why the work folder could not be deleted").isNull();
        assertThat(work).doesNotExist();
        assertThat(Files.readString(Path.of("/proc/self/mountinfo"))).as("mounts").doesNotContain(work.toString());
    }
}
