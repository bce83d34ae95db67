package gfx.tick1.command.grade;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.TestTmpfs;
import gfx.tick1.Tick1Jvm;
import gfx.tick1.command.shared.grader.cohort.StoredCode;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A cohort graded while the grader's own disk is short of space: a failure that may be the disk's
 * doing is never stored as the student's result. The grader's temporary folder is a file system
 * of 64 MiB (a tmpfs this test mounts, so grading as root where mounting is allowed), less than
 * the 256 MiB one run's output folder may hold.
 */
@Order(6)   // one of the longest classes: it starts early (junit-platform.properties)
class GradeCohortDiskTest {

    @TempDir
    Path dir;

    private Path mounted;

    @BeforeAll
    static void theSandboxCanRunHere() throws InterruptedException {
        GradeAttackTest.theSandboxCanRunHere();
    }

    @AfterEach
    void unmount() throws Exception {
        if (mounted != null) {
            TestTmpfs.unmount(mounted);
        }
    }

    @Test
    void aFailureOnAGraderWithLessRoomThanARunMayWriteIsGradedFromWhatItsRunHit() throws Exception {
        // 64 MiB is less than the 256 MiB one run's output may hold, but the failing run writes next to nothing:
        // it never hit the disk's end, so its failure is its own.
        Path small = temporaryFolder("small-tmp", "size=64m");
        StudentSolution correct = StudentSolution.correct();
        Path zip = download(correct, correct.editRenderer("return image;",
                "image.setRGB(0, 0, 0xFFFFFF); return image;"));
        Path report = dir.resolve("report");

        String run = grade(small, zip, report);

        assertThat(run).as("what the grade printed").contains("1 passed, 1 failed, 0 not graded")
                .doesNotContain("not graded:");
        assertThat(Files.readString(report.resolve("grades.csv"))).as("grades.csv")
                .contains("Participant 101,", "Participant 102,").contains("1.00").contains("0.00");
        assertThat(stored(report)).as("results stored: both").hasSize(2);
    }

    @Test
    void aFailureOnAGraderDiskFullBeforeItsRunIsNotGradedNeverFailed() throws Exception {
        // 10 MiB free from the start, less than the 16 MiB of a full disk: as full as another job may hold it while
        // a run is compiled, where a correct run fails as a wrong one does. The passing run passes; the failing one
        // is not graded.
        Path nearlyFull = temporaryFolder("nearly-full-tmp", "size=64m");
        Files.write(nearlyFull.resolve("someone else's file"), new byte[54 << 20]);
        StudentSolution correct = StudentSolution.correct();
        Path zip = download(correct, correct.editRenderer("return image;",
                "image.setRGB(0, 0, 0xFFFFFF); return image;"));

        String run = grade(nearlyFull, zip, dir.resolve("report"));

        assertThat(run).as("what the grade printed").contains("1 passed, 0 failed, 1 not graded");
    }

    @Test
    void aGraderTemporaryFolderOutOfFilesFailsNoCorrectSubmission() throws Exception {
        // Room for far more bytes than a run may write, and for a few dozen files and folders: enough for the
        // grader's own folders and the sources, not for every class file the compiler writes.
        Path few = temporaryFolder("few-files-tmp", "size=400m,nr_inodes=46");
        StudentSolution correct = StudentSolution.correct();
        Path report = dir.resolve("report");

        String run = grade(few, download(correct, correct), report);

        assertThat(Files.readString(report.resolve("grades.csv")))
                .as("grades.csv: the grader's disk, out of files, is no student's failure (%s)", run)
                .doesNotContain("0.00").doesNotContain("FAILED");
    }

    @Test
    void aStudentWhoseCodeSaysTheDiskIsFullOnARoomyDiskFailsAndIsNotLeftUngraded() throws Exception {
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx--x--x"));
        Path roomy = Files.createDirectory(dir.resolve("tmp"), PosixFilePermissions.asFileAttribute(
                PosixFilePermissions.fromString("rwx--x--x")));
        StudentSolution correct = StudentSolution.correct();
        // The kernel's words for ENOSPC, thrown by the student's own code, on a disk with room to spare.
        Path zip = download(correct, correct.editRenderer("return image;",
                "if (image != null) { throw new IllegalStateException(\"No space left on device\"); } return image;"));
        Path report = dir.resolve("report");

        String run = grade(roomy, zip, report);

        assertThat(run).as("what the grade printed: the code's own words chose no grade").doesNotContain("not graded:");
        assertThat(Files.readString(report.resolve("grades.csv"))).as("grades.csv: the failing student gets 0.00")
                .contains("Participant 102,").contains("0.00");
        assertThat(stored(report)).as("results stored: both").hasSize(2);
    }

    @Test
    void aCompileThatWritesMoreClassFilesThanACapFailsThatStudentAloneAndNeverFillsTheGraderDisk() throws Exception {
        // Room for the grader's own files and the files and folders one run may make, but not for 15,000 more:
        // a burst of class files beyond the output folder's cap that reached it would fill it.
        Path tight = temporaryFolder("tight-tmp", "size=1g,nr_inodes=11000");
        StudentSolution correct = StudentSolution.correct();
        // A short source for each class file: javac writes 15,000 files, more than the 10,000 a run may make.
        StringBuilder classes = new StringBuilder();
        for (int i = 0; i < 15_000; i++) {
            classes.append("static class C").append(i).append(" {}\n");
        }
        String sphere = correct.sphere();
        int end = sphere.lastIndexOf('}');
        StudentSolution burst = new StudentSolution(sphere.substring(0, end) + classes + "}\n", correct.renderer());
        Path report = dir.resolve("report");

        String run = grade(tight, download(correct, burst), report, 2);

        assertThat(run).as("what the grade printed: both graded").contains("1 passed, 1 failed")
                .doesNotContain("not graded:");
        assertThat(Files.readString(report.resolve("feedback").resolve("Failing Student_102_assignsubmission_file_")
                .resolve("feedback.txt"))).as("the student's feedback: the burst fails them, by the cap's words")
                .contains("made more than 10000 files and folders");
        assertThat(Files.readString(report.resolve("grades.csv"))).as("grades.csv: the neighbour passes (%s)", run)
                .containsPattern("Participant 101,.*1\\.00");
        assertThat(stored(report)).as("results stored: both").hasSize(2);
    }

    /**
     * A temporary folder for the grader, {@code name} in the test's folder: a tmpfs this test mounts
     * with {@code options} (size, inodes) and unmounts; the test is skipped where it cannot (not root).
     */
    private Path temporaryFolder(String name, String options) throws IOException, InterruptedException {
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx--x--x"));
        Path folder = Files.createDirectory(dir.resolve(name));
        TestTmpfs.mount(folder, options + ",mode=0711");
        mounted = folder;
        return folder;
    }

    /** A download of two students: one passing, one whose image is wrong. */
    private Path download(StudentSolution passing, StudentSolution failing) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ZipOutputStream zip = new ZipOutputStream(bytes)) {
            String[] folders = {"Passing Student_101_assignsubmission_file_/",
                "Failing Student_102_assignsubmission_file_/"};
            StudentSolution[] solutions = {passing, failing};
            for (int i = 0; i < 2; i++) {
                for (String[] file : new String[][] {{"Sphere.java", solutions[i].sphere()},
                        {"Renderer.java", solutions[i].renderer()}}) {
                    zip.putNextEntry(new ZipEntry(folders[i] + file[0]));
                    zip.write(file[1].getBytes(StandardCharsets.UTF_8));
                    zip.closeEntry();
                }
            }
        }
        return Files.write(dir.resolve("download.zip"), bytes.toByteArray());
    }

    /** A cohort grade in a JVM of its own with {@code temporary} as its temporary folder: what it printed. */
    private static String grade(Path temporary, Path zip, Path report) throws IOException, InterruptedException {
        return grade(temporary, zip, report, 1);
    }

    /**
     * A cohort grade as above, by {@code jobs} jobs at once; without the look-alike check, which reads and writes
     * only the report folder, never the temporary one.
     */
    private static String grade(Path temporary, Path zip, Path report, int jobs)
            throws IOException, InterruptedException {
        List<String> command = CliRun.java();
        command.add("-Djava.io.tmpdir=" + temporary);
        command.addAll(Tick1Jvm.mainClass());
        command.addAll(List.of("grade", "--submissions", zip.toString(), "--report", report.toString(),
                "--width", "160", "--height", "120", "--time-limit", "30", "--jobs", Integer.toString(jobs),
                "--no-lookalikes"));
        Process grade = new ProcessBuilder(command).redirectErrorStream(true).start();
        grade.getOutputStream().close();
        byte[] printed = grade.getInputStream().readAllBytes();
        // Not a timing check: a bound on how long to wait for a grade that may hang.
        assertThat(grade.waitFor(5, TimeUnit.MINUTES)).as("the grade ended").isTrue();
        return new String(printed, StandardCharsets.UTF_8);
    }

    private static List<Path> stored(Path report) throws IOException {
        Path state = report.resolve(CohortCommand.STATE_FOLDER);
        if (!Files.isDirectory(state)) {
            return List.of();
        }
        try (Stream<Path> entries = Files.list(state)) {
            return entries.filter(p -> !p.getFileName().toString().startsWith(".")
                    && !p.getFileName().toString().equals(StoredCode.FOLDER)).toList();
        }
    }
}
