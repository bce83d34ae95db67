package gfx.tick1.command.shared.grader.sandbox;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

/**
 * The host's files a run sees: the JDK it runs on and the libraries that JDK loads, nothing else
 * of the host's. Each file is bound into the run's own root file system (bwrap's, in memory) at
 * the path the JVM or the loader asks for (a link to a file is bound as the file it leads to),
 * with the links to folders on the way made there too; the folders around them are the run's own,
 * so a run sees no other name in them, and nothing it looks up there is remembered once it has
 * ended.
 */
final class SystemFiles {

    /**
     * The JDK's files a run of the harness uses, headless: the launcher; the modules, with the
     * class data archives (the second for heaps without compressed pointers); the VM and the
     * native libraries of java.base (sockets' included, which find no network), of ImageIO's
     * images (awt, mlib_image, lcms, and the JPEG codec, javajpeg) and of the management the
     * harness reads its CPU time through (with the platform's beans, which ManagementFactory
     * loads); the time zones; the helper that starts processes; and the configuration read at
     * start or by security (javax.crypto's policy files too) and logging. The rest of the JDK (the
     * X11 toolkit, sound, fonts, printing, JFR, the debugger's agents, smart cards, ...) a run
     * never loads, and nothing of it is shown.
     */
    private static final List<String> JDK_FILES = List.of("bin/java", "release", "lib/modules",
            "lib/server/libjvm.so", "lib/server/classes.jsa", "lib/server/classes_nocoops.jsa", "lib/jvm.cfg",
            "lib/libjli.so", "lib/libjava.so", "lib/libjimage.so", "lib/libzip.so", "lib/libnio.so", "lib/libnet.so",
            "lib/libextnet.so",
            "lib/libverify.so", "lib/libjsvml.so", "lib/libmanagement.so", "lib/libmanagement_ext.so", "lib/libawt.so",
            "lib/libawt_headless.so", "lib/libmlib_image.so", "lib/liblcms.so", "lib/libjavajpeg.so", "lib/tzdb.dat",
            "lib/jspawnhelper", "conf/security/java.security",
            "conf/security/policy/unlimited/default_US_export.policy",
            "conf/security/policy/unlimited/default_local.policy",
            "conf/security/policy/limited/default_US_export.policy",
            "conf/security/policy/limited/default_local.policy",
            "conf/security/policy/limited/exempt_local.policy", "conf/logging.properties", "conf/net.properties");
    /** Glibc's files for the runs' locale, C.UTF-8 (built into glibc from 2.35; in these files before). */
    private static final Path LOCALE = Path.of("/usr/lib/locale/C.utf8");
    /** Glibc's ldd, which lists the libraries a program or library loads and where the loader finds them. */
    private static final Path LDD = Path.of("/usr/bin/ldd");
    /** More links than this on the way to one file is a loop. */
    private static final int MOST_LINKS = 40;

    /**
     * What ldd said of each list of programs in this JVM: their libraries do not change while tick1 runs, and
     * ldd starts the loader anew for each program, which costs more than the rest of finding the host's files.
     * A process that makes many sandboxes (the tests' own JVM, running diffs in-process) asks it once.
     */
    private static final Map<List<Path>, List<Path>> LOADED_BY = new ConcurrentHashMap<>();

    /** A symbolic link of the host's to a folder on the way to a file, made the same in the run's root. */
    record Link(Path at, String target) {
    }

    /** A file of the host's, by its real path, and where the run sees it: the path asked for, its folders real. */
    record Bound(Path real, Path at) {
    }

    /** The files, each by its real path and where the run sees it. */
    private final List<Bound> files;
    /** The links to folders on the way to them, where the paths asked for go through links. */
    private final List<Link> links;

    SystemFiles(List<Bound> files, List<Link> links) {
        this.files = List.copyOf(files);
        this.links = List.copyOf(links);
    }

    /**
     * The files a run of {@code javaHome}'s java needs: the JDK's files the harness uses (the
     * links there into /etc followed), every library ldd says the launcher and those of the JDK
     * load, and the locale's files; and {@code programs} with the libraries they load.
     *
     * @throws IOException when the JDK's files cannot be listed or ldd cannot be run
     */
    static SystemFiles of(Path javaHome, List<Path> programs) throws IOException, InterruptedException {
        Set<Path> wanted = new LinkedHashSet<>(programs);
        JDK_FILES.forEach(file -> wanted.add(javaHome.resolve(file)));
        if (Files.isDirectory(LOCALE)) {
            // Every file, those in its folders too: glibc refuses the locale without LC_MESSAGES/SYS_LC_MESSAGES.
            try (var entries = Files.walk(LOCALE)) {
                entries.filter(Files::isRegularFile).forEach(wanted::add);
            }
        }
        List<Path> loaders = wanted.stream()
                .filter(path -> path.getFileName().toString().endsWith(".so") || path.endsWith("bin/java")
                        || programs.contains(path))
                .filter(Files::isRegularFile).toList();
        wanted.addAll(librariesLoadedBy(loaders));
        return following(wanted);
    }

    /**
     * The files {@code paths} lead to, by their real paths, with the links on the way; none for
     * a path that leads nowhere or to a folder.
     */
    static SystemFiles following(Iterable<Path> paths) throws IOException {
        Set<Bound> files = new LinkedHashSet<>();
        Set<Link> links = new LinkedHashSet<>();
        for (Path path : paths) {
            Path absolute = path.toAbsolutePath().normalize();
            if (absolute.getParent() == null) {
                continue;
            }
            Set<Link> on = new LinkedHashSet<>();
            Path folder = follow(absolute.getParent(), on, 0);
            Path at = folder == null ? null : folder.resolve(absolute.getFileName());
            Path real = at == null ? null : follow(at, new LinkedHashSet<>(), 0);
            if (real != null && Files.isRegularFile(real, LinkOption.NOFOLLOW_LINKS)) {
                links.addAll(on);
                files.add(new Bound(real, at));
            }
        }
        return new SystemFiles(new ArrayList<>(files), new ArrayList<>(links));
    }

    /** The real paths of the files. */
    List<Path> files() {
        return files.stream().map(Bound::real).distinct().toList();
    }

    /** Where the run sees them, and the links to folders made on the way. */
    List<Path> pathsSeen() {
        List<Path> seen = new ArrayList<>(files.stream().map(Bound::at).toList());
        seen.addAll(links.stream().map(Link::at).toList());
        return seen;
    }

    /**
     * bwrap's arguments that make them in the run's root: the folders that hold the links, the
     * links, and each file bound read-only where the run sees it (bwrap makes the folders above it).
     */
    List<String> bwrapArguments() {
        List<String> arguments = new ArrayList<>();
        Set<Path> folders = new LinkedHashSet<>();
        for (Link link : links) {
            Path folder = link.at().getParent();
            if (folder != null && folder.getParent() != null && folders.add(folder)) {
                arguments.addAll(List.of("--dir", folder.toString()));
            }
            arguments.addAll(List.of("--symlink", link.target(), link.at().toString()));
        }
        for (Bound file : files) {
            arguments.addAll(List.of("--ro-bind", file.real().toString(), file.at().toString()));
        }
        return arguments;
    }

    /**
     * The real path of {@code path}, an absolute path without "." or "..", adding to {@code links}
     * each link on the way (by the path it has, whose folders are real); null when it leads nowhere.
     */
    private static Path follow(Path path, Set<Link> links, int depth) throws IOException {
        if (depth > MOST_LINKS) {
            return null;
        }
        Path real = path.getRoot();
        for (Path name : path) {
            Path next = real.resolve(name);
            if (Files.isSymbolicLink(next)) {
                String target = Files.readSymbolicLink(next).toString();
                links.add(new Link(next, target));
                real = follow(real.resolve(target).normalize(), links, depth + 1);
                if (real == null) {
                    return null;
                }
            } else if (Files.exists(next, LinkOption.NOFOLLOW_LINKS)) {
                real = next;
            } else {
                return null;
            }
        }
        return real;
    }

    /**
     * The libraries ldd says {@code programs} load, by the paths the loader opens them at
     * (its own included); none that ldd cannot find.
     */
    private static List<Path> librariesLoadedBy(List<Path> programs) throws IOException, InterruptedException {
        List<Path> known = LOADED_BY.get(programs);
        if (known == null) {
            known = askLdd(programs);
            LOADED_BY.put(List.copyOf(programs), known);
        }
        return known;
    }

    /** The libraries ldd says {@code programs} load, as {@link #librariesLoadedBy}, asked anew. */
    private static List<Path> askLdd(List<Path> programs) throws IOException, InterruptedException {
        if (programs.isEmpty()) {
            return List.of();
        }
        List<String> command = new ArrayList<>(List.of(LDD.toString()));
        programs.forEach(program -> command.add(program.toString()));
        Process ldd = Sandbox.processFor(command).redirectErrorStream(true).start();
        ldd.getOutputStream().close();
        byte[] said = ldd.getInputStream().readNBytes(1 << 20);
        if (!ldd.waitFor(60, TimeUnit.SECONDS)) {
            ldd.destroyForcibly();
            throw new IOException("ldd did not end");
        }
        List<Path> libraries = new ArrayList<>();
        for (String line : new String(said, StandardCharsets.UTF_8).lines().toList()) {
            // "\tlibz.so.1 => /lib/x86_64-linux-gnu/libz.so.1 (0x...)" and "\t/lib64/ld-linux-x86-64.so.2 (0x...)"
            String entry = line.strip();
            int arrow = entry.indexOf("=> ");
            String where = arrow >= 0 ? entry.substring(arrow + 3) : entry;
            int address = where.lastIndexOf(" (0x");
            if (where.startsWith("/") && address > 0) {
                libraries.add(Path.of(where.substring(0, address)));
            }
        }
        if (libraries.isEmpty()) {
            throw new IOException("ldd listed no library that java loads");
        }
        return List.copyOf(libraries);
    }
}
