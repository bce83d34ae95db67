package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;

/**
 * A stand-in for bwrap where the kernel refuses it new namespaces, as in Docker's default container or a chroot: it
 * says what Debian 12's bwrap says there, and fails. The system property tick1.grade.bwrap names it.
 */
public final class RefusedNamespaces {

    /** Debian 12's bubblewrap 0.8's words where unprivileged user namespaces are not allowed. */
    public static final String WHAT_BWRAP_SAYS = "bwrap: No permissions to create new namespace, likely because the "
            + "kernel does not allow non-privileged user namespaces.";

    private RefusedNamespaces() {
    }

    /**
     * Writes the stand-in into {@code folder} and returns it; the folder is opened to every user, since as root the
     * sandbox starts bwrap as a user of its own.
     */
    public static Path bwrap(Path folder) throws IOException {
        Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwxr-xr-x"));
        Path bwrap = folder.resolve("bwrap-refused");
        Files.writeString(bwrap, "#!/bin/sh\necho '" + WHAT_BWRAP_SAYS + " See <https://deb.li/bubblewrap> or "
                + "<file:///usr/share/doc/bubblewrap/README.Debian.gz>.' >&2\nexit 1\n");
        Files.setPosixFilePermissions(bwrap, PosixFilePermissions.fromString("rwxr-xr-x"));
        return bwrap;
    }
}
