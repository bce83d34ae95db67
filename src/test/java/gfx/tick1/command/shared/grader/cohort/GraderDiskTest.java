package gfx.tick1.command.shared.grader.cohort;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import gfx.tick1.TestTmpfs;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Whether a failed grade may be the grader's own disk's doing is decided from the disk, and the
 * answer does not hang on one program: without a stat that can count inodes, a roomy work folder
 * is still roomy, so a student's failure there is the student's, stored, and not "not graded".
 */
class GraderDiskTest {

    @TempDir
    Path dir;

    private Path work;

    @BeforeEach
    void roomyWorkFolder() throws IOException {
        work = Files.createDirectory(dir.resolve("work"));
        assumeThat(work.toFile().getUsableSpace()).as("the test's folder has room for a run")
                .isGreaterThanOrEqualTo(WorkFolder.RUN_SPACE);
    }

    /** A stat at {@code name} in the test's folder that prints {@code printed} and exits with {@code status}. */
    private Path stat(String name, String printed, int status) throws IOException {
        Path script = dir.resolve(name);
        Files.writeString(script, "#!/bin/sh\necho '" + printed + "'\nexit " + status + "\n");
        Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwx------"));
        return script;
    }

    @Test
    void aRoomyFolderIsRoomyWithoutAStatProgram() throws InterruptedException {
        assertThat(GraderDisk.shortOfSpace(work, dir.resolve("no-stat-here")))
                .as("why the disk may be at fault, with no stat on the machine").isNull();
    }

    @Test
    void aRoomyFolderIsRoomyWhenStatFails() throws IOException, InterruptedException {
        assertThat(GraderDisk.shortOfSpace(work, stat("failing-stat", "stat: unrecognized option '--file-system'", 1)))
                .as("why the disk may be at fault, with a stat that does not know the options").isNull();
    }

    /** Not a timing check: a bound on how long to wait for an answer that, without the fix, never comes. */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aStatThatDoesNotAnswerIsGivenUpAndTheFolderAskedByMakingAFile() throws IOException, InterruptedException {
        // It prints a count of too few inodes, then hangs as stat does on a network mount that does not answer.
        Path hanging = dir.resolve("hanging-stat");
        Files.writeString(hanging, "#!/bin/sh\necho '12 1000000'\nexec sleep 600\n");
        Files.setPosixFilePermissions(hanging, PosixFilePermissions.fromString("rwx------"));
        assertThat(GraderDisk.shortOfSpace(work, hanging))
                .as("why the disk may be at fault, with a stat that never ends (the folder takes a file)").isNull();
    }

    @Test
    void aRoomyFolderIsRoomyWhenStatPrintsSomethingElse() throws IOException, InterruptedException {
        assertThat(GraderDisk.shortOfSpace(work, stat("odd-stat", "File: \"/tmp\"", 0)))
                .as("why the disk may be at fault, with a stat that prints another form").isNull();
    }

    @Test
    void whereStatCannotTellAFolderThatTakesNoNewFileIsShort() throws IOException, InterruptedException {
        Path notAFolder = Files.createFile(dir.resolve("not-a-folder"));
        assertThat(GraderDisk.shortOfSpace(notAFolder, dir.resolve("no-stat-here")))
                .as("why the disk may be at fault, where no file can be made").contains("takes no new file or folder");
    }

    @Test
    void aFolderWithFewerFreeInodesThanARunMayMakeIsShort() throws IOException, InterruptedException {
        assertThat(GraderDisk.shortOfSpace(work, stat("full-stat", "12 1000000", 0)))
                .as("why the disk may be at fault, with 12 inodes free").contains("room for only 12 more files");
    }

    /** A stat that counts 12 inodes free while {@code run} exists, and plenty once it is gone. */
    private Path statFullWhile(Path run) throws IOException {
        Path script = dir.resolve("full-while-stat");
        Files.writeString(script, "#!/bin/sh\nif [ -e '" + run + "' ]; then echo '12 1000000'; "
                + "else echo '500000 1000000'; fi\n");
        Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwx------"));
        return script;
    }

    @Test
    void aDiskFullOnlyWithARunsOwnFilesIsTheRunsDoingNotTheGradersShortage() throws IOException, InterruptedException {
        Path run = Files.createDirectory(work.resolve("submission-0"));
        Files.createFile(run.resolve("f0-0"));

        assertThat(GraderDisk.shortOfSpaceBeyond(work, run, statFullWhile(run)))
                .as("why the disk may be at fault, when it is full only while the run's own files are there").isNull();
    }

    @Test
    void aDiskStillFullWithoutARunsOwnFilesIsTheGradersShortage() throws IOException, InterruptedException {
        Path run = Files.createDirectory(work.resolve("submission-0"));

        assertThat(GraderDisk.shortOfSpaceBeyond(work, run, stat("full-stat", "12 1000000", 0)))
                .as("why the disk may be at fault, when it stays full without the run's files")
                .contains("room for only 12 more files");
    }

    @Test
    void aFolderOnTheMachinesOwnStatIsRoomy() throws InterruptedException {
        assertThat(GraderDisk.shortOfSpace(work)).as("why the disk may be at fault, on this machine's disk").isNull();
    }
    @Test
    void aDiskWithLessRoomThanARunMayWriteIsShortOnlyOnceARunHasFilledIt() throws Exception {
        Path small = Files.createDirectory(dir.resolve("small"));
        TestTmpfs.mount(small, "size=64m");
        try {
            assertThat(GraderDisk.shortOfSpace(small)).as("64 MiB free: less than a run may write, but not full")
                    .isNull();
            Files.write(small.resolve("a run's output"), new byte[56 << 20]);
            assertThat(GraderDisk.shortOfSpace(small)).as("8 MiB free, after a run wrote the rest")
                    .contains("was full when its run failed");
        } finally {
            TestTmpfs.unmount(small);
        }
    }
}
