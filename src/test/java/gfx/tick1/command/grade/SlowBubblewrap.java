package gfx.tick1.command.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;

/**
 * A bubblewrap that waits 5 s before it runs, for a grade to be stopped while its sandbox is being made: the grade's
 * JVM is given it with {@link #jvmOption()}, and {@link #awaitBegun} waits until the grade has run it.
 *
 * @param began the file it touches as it begins
 * @param script the script itself
 */
record SlowBubblewrap(Path began, Path script) {

    /** One in {@code dir}. */
    static SlowBubblewrap in(Path dir) throws IOException {
        // The sandbox's check runs bubblewrap as a sandbox user, who may write only in a folder open to all.
        Path marks = Files.createDirectory(dir.resolve("marks"));
        Files.setPosixFilePermissions(marks, PosixFilePermissions.fromString("rwxrwxrwx"));
        Path began = marks.resolve("bubblewrap-began");
        Path script = Files.writeString(dir.resolve("slow-bwrap"), "#!/bin/sh\ntouch '" + began
                + "'\nsleep 5\nexec /usr/bin/bwrap \"$@\"\n");
        Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwxr-xr-x"));
        return new SlowBubblewrap(began, script);
    }

    String jvmOption() {
        return "-Dtick1.grade.bwrap=" + script;
    }

    /** Waits (at most a minute) for {@code grade} to run it. */
    void awaitBegun(Process grade) throws InterruptedException {
        for (int i = 0; i < 600 && grade.isAlive() && !Files.exists(began); i++) {
            Thread.sleep(100);
        }
    }
}
