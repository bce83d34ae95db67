package gfx.tick1.command.shared.grader.sandbox;

import gfx.tick1.command.shared.grader.sandbox.Sandbox.Bind;
import java.util.ArrayList;
import java.util.List;

/** What a run in the sandbox sees of the file systems: bwrap's mounts, and the grader's folders bound in. */
final class Mounts {

    private Mounts() {
    }

    /** bwrap's arguments that mount what a run sees: {@code system}, the host's files it shows, and {@code binds}. */
    static List<String> arguments(SystemFiles system, List<Bind> binds) {
        List<String> arguments = new ArrayList<>();
        // Of the host's files, the JDK and the libraries it loads, each on its own: no folder of the host's,
        // so neither tick1, nor the grader's temporary folder, nor any scene of the organiser's.
        arguments.addAll(system.bwrapArguments());
        // No file system a run can write but its output folder, which is sized and, as root, noexec: / and /dev
        // (bwrap's own, of half the host's memory) are read-only, and /dev/shm is an empty folder on that /dev.
        // No /proc at all. It numbers a process's files, as they are first looked at, from the count the kernel
        // numbers pipes and sockets by, one for the whole machine, so a run that looked at many could leave a
        // number for a later run to read; its files count what the whole machine did (stat, meminfo, pressure);
        // and a process may write its own memory through /proc/self/mem, code included, which would bring
        // native code into a run in Java alone. Without /proc the loader cannot find the launcher's libraries
        // from where java is ($ORIGIN), so it is told.
        arguments.addAll(List.of("--dir", "/proc", "--setenv", "LD_LIBRARY_PATH",
                Sandbox.javaHome().resolve("lib").toString(), "--dev", "/dev", "--remount-ro", "/dev"));
        for (Bind bind : binds) {
            arguments.addAll(List.of(bind.writable() ? "--bind" : "--ro-bind", bind.outside().toString(),
                    bind.inside()));
        }
        arguments.addAll(List.of("--remount-ro", "/", "--chdir", "/", "--"));
        return arguments;
    }
}
