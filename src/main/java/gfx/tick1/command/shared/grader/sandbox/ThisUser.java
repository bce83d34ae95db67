package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;

/**
 * The user this process runs as, told by the owner of {@code /proc/self}. What tick1 cleans up
 * after others must be this user's: anyone may make a file with a name tick1 gives, but only
 * root can make one that root owns.
 */
final class ThisUser {

    private static final Path PROC_SELF = Path.of("/proc/self");

    private ThisUser() {
    }

    /** This process's user id, or -1 where it cannot be told. */
    static int uid() {
        return uidOf(PROC_SELF, true);
    }

    /** Whether this process runs as root. */
    static boolean root() {
        return uid() == 0;
    }

    /** Whether {@code path} itself (a link is not followed) is there and owned by this process's user. */
    static boolean owns(Path path) {
        int uid = uid();
        return uid >= 0 && uidOf(path, false) == uid;
    }

    private static int uidOf(Path path, boolean follow) {
        try {
            Object uid = follow ? Files.getAttribute(path, "unix:uid")
                    : Files.getAttribute(path, "unix:uid", LinkOption.NOFOLLOW_LINKS);
            return uid instanceof Integer number ? number : -1;
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | SecurityException e) {
            return -1;
        }
    }
}
