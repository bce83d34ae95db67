package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * What the sandbox hides from the runs: every file of the host's but those they need, so a secret
 * (the organiser's scenes) that lies among those cannot be hidden.
 */
final class Secrets {

    private Secrets() {
    }

    /** The real path of {@code path}; null when it cannot be read (not there: nothing to hide). */
    static Path realPath(Path path) {
        try {
            return path.toRealPath();
        } catch (IOException e) {
            return null;
        }
    }

    /**
     * Refuses a secret the runs would see: one in the JDK {@code jdk} (its real path) or holding
     * it, or one that is, or is a folder that holds, one of {@code system}'s files or links (none
     * for a sandbox that shows the host's files as they are). Hiding it would take from the runs
     * what they need. A secret that cannot be read is not there to hide.
     */
    static void refuseWhatTheRunsSee(List<Path> secrets, SystemFiles system, Path jdk) throws Sandbox.CannotHide {
        List<Path> seen = new ArrayList<>(List.of(jdk));
        if (system != null) {
            seen.addAll(system.files());
            seen.addAll(system.pathsSeen());
        }
        for (Path secret : secrets) {
            Path real = realPath(secret);
            if (real == null) {
                continue;
            }
            boolean folder = Files.isDirectory(real);
            Path needed = real.startsWith(jdk) ? jdk
                    : seen.stream().filter(path -> path.startsWith(real)).findFirst().orElse(null);
            if (needed != null) {
                throw new Sandbox.CannotHide(secret + ": the runs need " + needed + ", so tick1 cannot hide "
                        + (folder ? "this folder's scenes" : "this scene") + " from the student's code without "
                        + "stopping every run: give the scenes a folder of their own");
            }
        }
    }
}
