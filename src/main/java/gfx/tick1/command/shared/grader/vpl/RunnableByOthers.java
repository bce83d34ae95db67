package gfx.tick1.command.shared.grader.vpl;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

/**
 * Whether a user other than the launcher's owner, VPL's unprivileged user, can run an installed tick1: pass
 * through every folder above the launcher (by the path written and by the real one, links followed), read and run
 * the launcher, and read its {@code lib} folder and the files in it. Only the permissions of others are read: the
 * jail's user is neither the owner nor in the group.
 */
final class RunnableByOthers {

    private static final int READ = 04;
    private static final int EXECUTE = 01;

    private RunnableByOthers() {
    }

    /**
     * Why VPL's user cannot run {@code launcher}, in words that end with what to do; null when it can, when
     * {@code launcher} is not on this machine (a path of the jail's host) or the file system has no POSIX modes.
     */
    static String problem(Path launcher) {
        try {
            if (!Files.exists(launcher)) {
                return null;
            }
            Path real = launcher.toRealPath();
            Set<Path> folders = new LinkedHashSet<>();
            for (Path path : List.of(launcher.toAbsolutePath().normalize(), real)) {
                for (Path above = path.getParent(); above != null; above = above.getParent()) {
                    folders.add(above);
                }
            }
            List<Path> sorted = new ArrayList<>(folders);
            sorted.sort((a, b) -> Integer.compare(a.getNameCount(), b.getNameCount()));
            for (Path folder : sorted) {
                if (lacks(folder, EXECUTE)) {
                    return fix(folder, "lets no other user through", "o+x");
                }
            }
            if (lacks(real, READ | EXECUTE)) {
                return fix(real, "cannot be read and run by other users", "o+rx");
            }
            Path lib = real.getParent().resolveSibling("lib");
            if (Files.isDirectory(lib)) {
                if (lacks(lib, READ | EXECUTE)) {
                    return fix(lib, "cannot be listed by other users", "o+rx");
                }
                try (Stream<Path> files = Files.list(lib)) {
                    for (Path file : files.sorted().toList()) {
                        if (lacks(file, READ)) {
                            return fix(file, "cannot be read by other users", "o+r");
                        }
                    }
                }
            }
            return null;
        } catch (IOException | UnsupportedOperationException e) {
            return null;
        }
    }

    private static boolean lacks(Path path, int bits) throws IOException {
        return ((int) Files.getAttribute(path, "unix:mode") & bits) != bits;
    }

    private static String fix(Path path, String what, String chmod) throws IOException {
        return String.format("%s %s (mode %04o), so VPL's user cannot run tick1: install tick1 where every user can "
                + "reach it (under /opt, say) and give --tick1 its launcher, or chmod %s %s", path, what,
                (int) Files.getAttribute(path, "unix:mode") & 07777, chmod, path);
    }
}
