package gfx.tick1;

import gfx.tick1.command.shared.grader.sandbox.Leftovers;
import gfx.tick1.command.shared.grader.sandbox.Sandbox;
import gfx.tick1.command.shared.grader.sandbox.StudentProcess;
import gfx.tick1.command.shared.grader.sandbox.WorkFolder;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.platform.launcher.LauncherSession;
import org.junit.platform.launcher.LauncherSessionListener;

/**
 * One class data sharing archive of tick1's harness for the whole test run, as a cohort makes one for its jobs: made
 * as the tests start, by a sandboxed run of the starter kit ({@link StudentProcess#withSharedArchive}), and named to
 * the grades through {@link StudentProcess#KEPT_ARCHIVE_PROPERTY}: the tests' own, and those of the tick1s that
 * {@link Tick1Jvm} starts. The tests grade hundreds of times, and each sandboxed JVM then finds javac's classes and
 * the harness's already parsed. A tick1 started as users start it (the README's student commands, VPL's evaluation)
 * or from the class path (the cohort tests that stop and resume a grade, the grades as another user) maps none, as a
 * user's single grade does not. Where there is no sandbox, or the archive cannot be made, the runs start without
 * one.
 *
 * <p>Made once per JVM, and kept while it runs: a test that runs the JUnit Platform itself opens a session of its own
 * inside the run's, and a runner may open one session after another. The archive sits in a work folder of tick1's
 * ({@link Leftovers#newWorkFolder}), readable by every user a cohort's jobs run as; it goes when the JVM ends, or,
 * when the JVM was killed, with the leftovers of the next grade. Found by the JUnit Platform through
 * {@code META-INF/services}.
 */
public final class HarnessArchiveSession implements LauncherSessionListener {

    /** The heap of the run that makes the archive: the compiler's, which the archive's run uses. */
    private static final int MEMORY_MEGABYTES = 256;

    /** Whether a session of this JVM has tried to make the archive. */
    private static boolean tried;

    @Override
    public void launcherSessionOpened(LauncherSession session) {
        synchronized (HarnessArchiveSession.class) {
            // Once; and not where whoever started the JVM named an archive, or none (a blank name).
            if (tried || System.getProperty(StudentProcess.KEPT_ARCHIVE_PROPERTY) != null) {
                return;
            }
            tried = true;
        }
        try {
            Path folder = Leftovers.newWorkFolder("grade");
            Runtime.getRuntime().addShutdownHook(new Thread(() -> WorkFolder.delete(folder)));
            Path archive = archiveIn(folder);
            if (archive != null) {
                System.setProperty(StudentProcess.KEPT_ARCHIVE_PROPERTY, archive.toString());
            }
        } catch (IOException | RuntimeException e) {
            // The runs start without an archive.
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The folder in {@code folder} that holds the archive, or null where it could not be made. */
    private static Path archiveIn(Path folder) throws IOException, InterruptedException {
        Sandbox sandbox;
        try {
            sandbox = Sandbox.confined();
        } catch (Sandbox.Unavailable e) {
            return null;
        }
        WorkFolder.readableByAll(folder);   // empty yet: only the folder itself
        Path harness = Files.createDirectory(folder.resolve("harness"));
        StudentProcess.writeHarness(harness);
        WorkFolder.readableByAll(harness);
        Path archive = Files.createDirectory(folder.resolve("archive"));
        Path run = Files.createDirectory(folder.resolve("run"));
        StudentProcess process = new StudentProcess(sandbox, harness, MEMORY_MEGABYTES);
        boolean made = process.withSharedArchive(archive, run) != process;
        WorkFolder.delete(run);
        WorkFolder.readableByAll(archive);
        return made ? archive : null;
    }
}
