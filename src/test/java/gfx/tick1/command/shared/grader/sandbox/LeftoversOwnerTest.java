package gfx.tick1.command.shared.grader.sandbox;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assumptions.assumeThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Anyone may make a folder with the name of a killed run's leftovers: tick1 removes only what its
 * own user owns, and its removal deletes a link as a link, never what the link leads to.
 */
class LeftoversOwnerTest {

    /** nobody's user id on Debian and most Linux systems. */
    private static final int OTHER_UID = 65534;

    @TempDir
    Path temporary;

    @Test
    void aFolderAndAFilterFileWithLeftoverNamesOwnedByAnotherUserAreLeftAlone() throws Exception {
        assumeThat(ThisUser.root()).as("only root can give a file to another user").isTrue();
        long gone = goneProcess();
        Path folder = Files.createDirectories(temporary.resolve("tick1-grade-" + gone + "-1").resolve("d"));
        Path filter = Files.writeString(temporary.resolve("tick1-seccomp-" + gone + "-2.bpf"), "filter");
        for (Path path : new Path[] {folder, folder.getParent(), filter}) {
            Files.setAttribute(path, "unix:uid", OTHER_UID, LinkOption.NOFOLLOW_LINKS);
        }

        Leftovers.remove(temporary, null);

        assertThat(folder).as("another user's folder named as a leftover").isDirectory();
        assertThat(filter).as("another user's file named as a filter file").exists();
    }

    @Test
    void aLinkInsideALeftoverIsRemovedAsALinkAndWhatItLeadsToIsUntouched() throws Exception {
        Path victim = Files.createDirectory(temporary.resolve("victim"));
        Files.writeString(victim.resolve("precious"), "precious");
        Files.setPosixFilePermissions(victim, PosixFilePermissions.fromString("rwxr-xr-x"));
        Path leftover = Files.createDirectory(temporary.resolve("tick1-grade-" + goneProcess() + "-1"));
        Files.createSymbolicLink(leftover.resolve("l"), victim);

        assertThat(Leftovers.remove(temporary, null)).as("what could not be removed").isNull();

        assertThat(leftover).as("the leftover").doesNotExist();
        assertThat(victim.resolve("precious")).as("the file the link led to").exists();
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(victim)))
                .as("the permissions of the folder the link led to").isEqualTo("rwxr-xr-x");
    }

    /** The id of a process that has ended. */
    private static long goneProcess() throws IOException, InterruptedException {
        Process done = new ProcessBuilder("/bin/true").start();
        assertThat(done.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(Leftovers.gone(done.pid())).as("process " + done.pid() + " is gone").isTrue();
        return done.pid();
    }
}
